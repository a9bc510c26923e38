#include "scene/validate.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <utility>

#include "spline/catmull_rom.h"

namespace enteron::scene {
namespace {

// Limits beyond which a scene is a mistake rather than a wish (they also keep counts far
// from overflow in the buffers sized from them).
constexpr double kMaxLength = 1000.0;             // m
constexpr std::size_t kMaxControlPoints = 100000;
constexpr double kMaxTimestep = 0.1;              // s
constexpr std::size_t kMaxSubsteps = 1000000;
constexpr std::size_t kMaxSubdivisions = 30;      // 2^-30 of the timestep is already below 1 ns
constexpr std::size_t kMaxAttachments = 100000;

// Shortest text that reads back as the same double ("-1", not "-1.000000"). to_chars
// ignores the locale, which a host program may have changed.
std::string format(double value) {
    if (std::isnan(value)) return "nan";
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

template <typename Integer>
std::string format(Integer value) {
    return std::to_string(value);
}

std::string format(const Vec3& v) {
    return "[" + format(v[0]) + ", " + format(v[1]) + ", " + format(v[2]) + "]";
}

std::string indexed(const std::string& name, std::size_t index) {
    return name + "[" + std::to_string(index) + "]";
}

// One value under test, named for messages. Each check throws on failure and returns
// *this, so checks chain: check(r, Field::radius).above(0.0).below(length, "...").
template <typename T>
class Checked {
public:
    Checked(T value, std::string name, ErrorCode code)
        : value_(value), name_(std::move(name)), code_(code) {
        if constexpr (std::is_floating_point_v<T>) {
            if (!std::isfinite(value_)) fail("must be finite");
        }
    }

    // bound_name, when given, says where the bound comes from: "< intestine.length (6)".
    const Checked& above(T bound, const std::string& bound_name = {}) const {
        return require(value_ > bound, ">", bound, bound_name);
    }
    const Checked& at_least(T bound, const std::string& bound_name = {}) const {
        return require(value_ >= bound, ">=", bound, bound_name);
    }
    const Checked& below(T bound, const std::string& bound_name = {}) const {
        return require(value_ < bound, "<", bound, bound_name);
    }
    const Checked& at_most(T bound, const std::string& bound_name = {}) const {
        return require(value_ <= bound, "<=", bound, bound_name);
    }

    [[noreturn]] void fail(const std::string& requirement) const {
        throw Error(code_, name_ + " " + requirement + ", got " + format(value_));
    }

private:
    const Checked& require(bool ok, const char* relation, T bound,
                           const std::string& bound_name) const {
        if (!ok) {
            const std::string bound_text =
                bound_name.empty() ? format(bound) : bound_name + " (" + format(bound) + ")";
            fail(std::string("must be ") + relation + " " + bound_text);
        }
        return *this;
    }

    T value_;
    std::string name_;
    ErrorCode code_;
};

class Validator {
public:
    explicit Validator(const FieldNames& names) : names_(names) {}

    std::string name(Field field) const { return names_[field]; }

    template <typename T>
    Checked<T> check(T value, Field field) const {
        return Checked<T>(value, name(field), names_.code);
    }
    template <typename T>
    Checked<T> check_element(T value, Field field, std::size_t index) const {
        return Checked<T>(value, indexed(name(field), index), names_.code);
    }
    void check_finite(const Vec3& v, Field field) const {
        for (std::size_t k = 0; k < 3; ++k) check_element(v[k], field, k);
    }
    [[noreturn]] void fail(const std::string& name, const std::string& message) const {
        throw Error(names_.code, name + " " + message);
    }

    void intestine(const IntestineConfig& intestine) const;
    void shape(const IntestineConfig& intestine) const;
    void solver(const SolverConfig& solver) const;
    void damping(const DampingConfig& damping) const;
    void mesentery(const MesenteryConfig& mesentery) const;
    void pinned(const PinnedConfig& pinned, std::size_t control_points) const;
    void collision(const CollisionConfig& collision, double radius) const;
    void obstacle(const collision::Obstacle& obstacle, std::size_t index) const;

private:
    const FieldNames& names_;
};

void Validator::intestine(const IntestineConfig& intestine) const {
    check(intestine.length, Field::length).above(0.0).at_most(kMaxLength);
    check(intestine.radius, Field::radius).above(0.0).below(intestine.length, name(Field::length));
    check(intestine.control_points, Field::control_points)
        .at_least(spline::kMinControlPoints)
        .at_most(kMaxControlPoints);
    check(intestine.linear_density, Field::linear_density).above(0.0);
    if (intestine.stretch_stiffness) {
        check(*intestine.stretch_stiffness, Field::stretch_stiffness).at_least(0.0);
    }
    if (intestine.bend_stiffness) check(*intestine.bend_stiffness, Field::bend_stiffness).at_least(0.0);
    shape(intestine);
}

// Only the fields of the chosen kind matter; the others are never read.
void Validator::shape(const IntestineConfig& intestine) const {
    const ShapeConfig& shape = intestine.shape;
    check(static_cast<int32_t>(shape.kind), Field::shape_kind)
        .at_least(static_cast<int32_t>(ShapeKind::line))
        .at_most(static_cast<int32_t>(ShapeKind::points));
    // Neighbouring legs or turns closer than a diameter would start interpenetrated.
    const std::string diameter = "2 x " + name(Field::radius);
    switch (shape.kind) {
        case ShapeKind::line: {
            check_finite(shape.center, Field::shape_center);
            check_finite(shape.direction, Field::shape_direction);
            const Vec3& d = shape.direction;
            const double squared_length = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            // Normalising needs a length that is neither zero nor overflowing.
            if (!(squared_length > 0.0)) {
                fail(name(Field::shape_direction), "must be non-zero, got " + format(d));
            }
            if (!std::isfinite(squared_length)) {
                fail(name(Field::shape_direction), "must have a finite length, got " + format(d));
            }
            break;
        }
        case ShapeKind::serpentine:
            check_finite(shape.center, Field::shape_center);
            check(shape.leg_length, Field::shape_leg_length).above(0.0);
            check(shape.leg_spacing, Field::shape_leg_spacing).at_least(2.0 * intestine.radius, diameter);
            break;
        case ShapeKind::helix:
            check_finite(shape.center, Field::shape_center);
            check(shape.helix_radius, Field::shape_helix_radius).above(0.0);
            check(shape.helix_pitch, Field::shape_helix_pitch).at_least(2.0 * intestine.radius, diameter);
            break;
        case ShapeKind::points: {
            const std::size_t n = intestine.control_points;
            const std::string points = name(Field::shape_points);
            if (shape.points.size() != 3 * n && names_.shape_points_nested) {
                fail(points, "must hold " + format(n) + " points (" + name(Field::control_points) +
                                 "), got " + format(shape.points.size() / 3));
            }
            if (shape.points.size() != 3 * n) {
                fail(points, "must hold " + format(3 * n) + " values (" +
                                 name(Field::control_points) + " x 3), got " + format(shape.points.size()));
            }
            for (std::size_t i = 0; i < shape.points.size(); ++i) {
                const std::string element = names_.shape_points_nested
                                                ? indexed(indexed(points, i / 3), i % 3)
                                                : indexed(points, i);
                Checked<double>(shape.points[i], element, names_.code);
            }
            break;
        }
    }
}

void Validator::solver(const SolverConfig& solver) const {
    check(static_cast<int32_t>(solver.integrator), Field::integrator)
        .at_least(static_cast<int32_t>(IntegratorKind::rk4))
        .at_most(static_cast<int32_t>(IntegratorKind::implicit_euler));
    check(solver.timestep, Field::timestep).above(0.0).at_most(kMaxTimestep);
    check(solver.max_substeps, Field::max_substeps).at_least(1).at_most(kMaxSubsteps);
    check(solver.max_subdivisions, Field::max_subdivisions).at_most(kMaxSubdivisions);
    check(solver.max_speed, Field::max_speed).above(0.0);
}

void Validator::damping(const DampingConfig& damping) const {
    check(damping.drag, Field::drag).at_least(0.0);
    check(damping.stretch, Field::stretch_damping).at_least(0.0);
    check(damping.bend, Field::bend_damping).at_least(0.0);
}

void Validator::mesentery(const MesenteryConfig& mesentery) const {
    check_finite(mesentery.root_start, Field::mesentery_root_start);
    check_finite(mesentery.root_end, Field::mesentery_root_end);
    check(mesentery.attachments, Field::mesentery_attachments).at_least(1).at_most(kMaxAttachments);
    check(mesentery.stiffness, Field::mesentery_stiffness).at_least(0.0);
    check(mesentery.rest_length, Field::mesentery_rest_length).at_least(0.0);
}

void Validator::pinned(const PinnedConfig& pinned, std::size_t control_points) const {
    check(pinned.ends, Field::pinned_ends).at_least(pin_none).at_most(pin_both);
    for (std::size_t i = 0; i < pinned.points.size(); ++i) {
        check_element(std::size_t{pinned.points[i]}, Field::pinned_points, i)
            .below(control_points, name(Field::control_points));
    }
}

void Validator::collision(const CollisionConfig& collision, double radius) const {
    check(collision.sphere_spacing, Field::sphere_spacing).at_least(0.0).at_most(radius, name(Field::radius));
    check(collision.contact.stiffness, Field::contact_stiffness).at_least(0.0);
    check(collision.contact.damping, Field::contact_damping).at_least(0.0);
    check(collision.contact.friction, Field::contact_friction).at_least(0.0);
    check(collision.contact.slip_speed, Field::contact_slip_speed).above(0.0);
}

void Validator::obstacle(const collision::Obstacle& o, std::size_t index) const {
    using collision::ObstacleKind;
    const std::string base = indexed(name(Field::obstacle), index);
    const auto field = [&](const char* key) { return base + "." + key; };
    Checked<int32_t>(static_cast<int32_t>(o.kind), field("kind"), names_.code)
        .at_least(static_cast<int32_t>(ObstacleKind::box_inside))
        .at_most(static_cast<int32_t>(ObstacleKind::capsule));
    const auto finite = [&](const Vec3& v, const char* key) {
        for (std::size_t k = 0; k < 3; ++k) Checked<double>(v[k], indexed(field(key), k), names_.code);
    };
    switch (o.kind) {
        case ObstacleKind::box_inside:
            finite(o.center, "center");
            for (std::size_t k = 0; k < 3; ++k)
                Checked<double>(o.extent[k], indexed(field("half_extents"), k), names_.code).above(0.0);
            break;
        case ObstacleKind::plane:
            finite(o.center, "point");
            finite(o.extent, "normal");
            if (o.extent[0] == 0.0 && o.extent[1] == 0.0 && o.extent[2] == 0.0)
                fail(field("normal"), "must not be zero, got [0, 0, 0]");
            {
                // Its length must be computable to normalise it.
                const double length2 = o.extent[0] * o.extent[0] + o.extent[1] * o.extent[1] + o.extent[2] * o.extent[2];
                if (!(length2 > 0.0) || !std::isfinite(length2))
                    fail(field("normal"), "must have a length between 1e-150 and 1e150, got " + format(o.extent));
            }
            break;
        case ObstacleKind::sphere:
            finite(o.center, "center");
            Checked<double>(o.radius, field("radius"), names_.code).above(0.0);
            break;
        case ObstacleKind::capsule:
            finite(o.center, "start");
            finite(o.extent, "end");
            Checked<double>(o.radius, field("radius"), names_.code).above(0.0);
            break;
    }
}

FieldNames make_field_names(ErrorCode code, bool shape_points_nested,
                            std::initializer_list<std::pair<Field, const char*>> entries) {
    FieldNames names{code, shape_points_nested, {}};
    for (const auto& [field, name] : entries) names.names[static_cast<std::size_t>(field)] = name;
    return names;
}

}  // namespace

const FieldNames& json_field_names() {
    static const FieldNames names = make_field_names(
        ErrorCode::invalid_scene, true,
        {
            {Field::length, "intestine.length"},
            {Field::radius, "intestine.radius"},
            {Field::control_points, "intestine.control_points"},
            {Field::linear_density, "intestine.linear_density"},
            {Field::stretch_stiffness, "intestine.stretch_stiffness"},
            {Field::bend_stiffness, "intestine.bend_stiffness"},
            {Field::shape_kind, "intestine.shape.kind"},
            {Field::shape_center, "intestine.shape.center"},
            {Field::shape_direction, "intestine.shape.direction"},
            {Field::shape_leg_length, "intestine.shape.leg_length"},
            {Field::shape_leg_spacing, "intestine.shape.leg_spacing"},
            {Field::shape_helix_radius, "intestine.shape.helix_radius"},
            {Field::shape_helix_pitch, "intestine.shape.helix_pitch"},
            {Field::shape_points, "intestine.shape.points"},
            {Field::integrator, "solver.integrator"},
            {Field::timestep, "solver.timestep"},
            {Field::max_substeps, "solver.max_substeps"},
            {Field::max_subdivisions, "solver.max_subdivisions"},
            {Field::max_speed, "solver.max_speed"},
            {Field::gravity, "gravity"},
            {Field::drag, "damping.drag"},
            {Field::stretch_damping, "damping.stretch"},
            {Field::bend_damping, "damping.bend"},
            {Field::mesentery_root_start, "mesentery.root[0]"},
            {Field::mesentery_root_end, "mesentery.root[1]"},
            {Field::mesentery_attachments, "mesentery.attachments"},
            {Field::mesentery_stiffness, "mesentery.stiffness"},
            {Field::mesentery_rest_length, "mesentery.rest_length"},
            {Field::pinned_ends, "pinned.ends"},
            {Field::pinned_points, "pinned.control_points"},
            {Field::sphere_spacing, "collision.sphere_spacing"},
            {Field::contact_stiffness, "collision.stiffness"},
            {Field::contact_damping, "collision.damping"},
            {Field::contact_friction, "collision.friction"},
            {Field::contact_slip_speed, "collision.slip_speed"},
            {Field::obstacle, "environment"},
        });
    return names;
}

const FieldNames& c_field_names() {
    static const FieldNames names = make_field_names(
        ErrorCode::invalid_argument, false,
        {
            {Field::length, "length_m"},
            {Field::radius, "radius_m"},
            {Field::control_points, "control_points"},
            {Field::linear_density, "linear_density_kg_per_m"},
            {Field::stretch_stiffness, "stretch_stiffness_N"},
            {Field::bend_stiffness, "bend_stiffness_N_m2"},
            {Field::shape_kind, "shape"},
            {Field::shape_center, "shape_center_m"},
            {Field::shape_direction, "shape_direction"},
            {Field::shape_leg_length, "shape_leg_length_m"},
            {Field::shape_leg_spacing, "shape_leg_spacing_m"},
            {Field::shape_helix_radius, "shape_helix_radius_m"},
            {Field::shape_helix_pitch, "shape_helix_pitch_m"},
            {Field::shape_points, "shape_points_xyz_m"},
            {Field::integrator, "integrator"},
            {Field::timestep, "timestep_s"},
            {Field::max_substeps, "max_substeps"},
            {Field::max_subdivisions, "max_subdivisions"},
            {Field::max_speed, "max_speed_m_per_s"},
            {Field::gravity, "gravity_m_per_s2"},
            {Field::drag, "drag_N_s_per_m2"},
            {Field::stretch_damping, "stretch_damping_N_s"},
            {Field::bend_damping, "bend_damping_N_m2_s"},
            {Field::mesentery_root_start, "mesentery_root_start_m"},
            {Field::mesentery_root_end, "mesentery_root_end_m"},
            {Field::mesentery_attachments, "mesentery_attachments"},
            {Field::mesentery_stiffness, "mesentery_stiffness_N_per_m"},
            {Field::mesentery_rest_length, "mesentery_rest_length_m"},
            {Field::pinned_ends, "pinned_ends"},
            {Field::pinned_points, "pinned_points"},
            {Field::sphere_spacing, "collision_sphere_spacing_m"},
            {Field::contact_stiffness, "contact_stiffness_N_per_m"},
            {Field::contact_damping, "contact_damping_N_s_per_m"},
            {Field::contact_friction, "contact_friction"},
            {Field::contact_slip_speed, "contact_slip_speed_m_per_s"},
            {Field::obstacle, "obstacle"},
        });
    return names;
}

void validate(const SceneConfig& config, const FieldNames& names) {
    const Validator validator(names);
    validator.intestine(config.intestine);
    validator.solver(config.solver);
    if (config.gravity) validator.check_finite(*config.gravity, Field::gravity);
    if (config.damping) validator.damping(*config.damping);
    if (config.mesentery) validator.mesentery(*config.mesentery);
    if (config.pinned) validator.pinned(*config.pinned, config.intestine.control_points);
    validator.collision(config.collision, config.intestine.radius);
    for (std::size_t i = 0; i < config.environment.size(); ++i) validator.obstacle(config.environment[i], i);
    for (std::size_t i = 0; i < config.tools.size(); ++i) {
        const std::string name = "tools[" + std::to_string(i) + "]";
        collision::validate_tool_settings(config.tools[i].settings, name, names.code);
        (void)collision::normalized_pose(config.tools[i].pose, name, names.code);
    }
}

void validate_obstacle(const collision::Obstacle& obstacle, std::size_t index, const FieldNames& names) {
    Validator(names).obstacle(obstacle, index);
}

}  // namespace enteron::scene
