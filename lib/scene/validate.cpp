// SPDX-License-Identifier: Apache-2.0
#include "scene/validate.h"

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "mechanics/clamped_ends.h"
#include "scene/checked_value.h"
#include "scene/plausible_ranges.h"
#include "scene/points_length.h"
#include "scene/shape_builder.h"
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
// A tool 1e200 m wide is finite but gave the bowel an infinite potential energy: upper
// bounds on its sizes keep every contact's depth, and so its energy, finite.
constexpr double kMaxToolRadius = 1.0;   // m, also the largest grasp margin
constexpr double kMaxToolLength = 10.0;  // m

std::string format(const Vec3& v) {
    return "[" + format_number(v[0]) + ", " + format_number(v[1]) + ", " + format_number(v[2]) + "]";
}

std::string indexed(const std::string& name, std::size_t index) {
    return name + "[" + std::to_string(index) + "]";
}

// "0-11, 40, 52-239": the indices (ascending) as ranges, at most a few of them.
std::string index_ranges(const std::vector<std::size_t>& indices) {
    constexpr std::size_t kMaxRanges = 6;
    std::string text;
    std::size_t ranges = 0;
    for (std::size_t i = 0; i < indices.size();) {
        std::size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
        if (ranges == kMaxRanges) return text + ", ...";
        text += (text.empty() ? "" : ", ") + std::to_string(indices[i]);
        if (j > i) text += "-" + std::to_string(indices[j]);
        ++ranges;
        i = j + 1;
    }
    return text;
}

const char* obstacle_kind_name(collision::ObstacleKind kind) {
    switch (kind) {
        case collision::ObstacleKind::box_inside: return "box_inside";
        case collision::ObstacleKind::plane: return "plane";
        case collision::ObstacleKind::sphere: return "sphere";
        case collision::ObstacleKind::capsule: return "capsule";
        case collision::ObstacleKind::mesh: return "mesh";
    }
    return "?";
}

// Refuses an obstacle with control points so far beyond its surface that their contacts
// would throw them out faster than the guard allows (StartClearance): every step of such a
// scene would fail.
void check_clearance(const collision::Obstacle& o, const std::string& name, ErrorCode code, const double* points,
                     std::size_t count, const StartClearance& clearance) {
    // Beyond this the escape speed passes max_speed.
    const double deepest_possible = clearance.max_speed / clearance.escape_rate - clearance.radius;
    const mechanics::FramePlacement frame = mechanics::placement_at(o.pose);
    std::vector<std::size_t> stuck;
    double deepest = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double depth = collision::beyond_surface(o, frame.to_local(point_at(points, i)));
        if (depth > 0.0 && depth > deepest_possible) {
            stuck.push_back(i);
            deepest = std::max(deepest, depth);
        }
    }
    if (stuck.empty()) return;
    const bool organ = o.kind == collision::ObstacleKind::sphere || o.kind == collision::ObstacleKind::capsule ||
                       (o.kind == collision::ObstacleKind::mesh && !o.field->outside_is_solid());
    const char* where = organ ? "inside it" : o.kind == collision::ObstacleKind::plane ? "behind it" : "outside it";
    const double escape = (deepest + clearance.radius) * clearance.escape_rate;
    throw Error(code, name + " (" + obstacle_kind_name(o.kind) + ") has control points " + index_ranges(stuck) +
                          " (" + std::to_string(stuck.size()) + " of " + std::to_string(count) + ") " + where +
                          ", up to " + format_rounded(deepest) + " m beyond its surface: its contacts would throw them "
                          "out at up to " + format_rounded(escape) + " m/s, past the guard's max_speed (" +
                          format_number(clearance.max_speed) + " m/s), so the scene cannot start. Move the obstacle "
                          "or the bowel's shape so that the bowel starts " +
                          (organ ? "outside every organ" : "within the cavity"));
}

class Validator {
public:
    Validator(const FieldNames& names, const FieldSet& given) : names_(names), given_(given) {}

    std::string name(Field field) const { return names_[field]; }

    template <typename T>
    Checked<T> check(T value, Field field) const {
        return Checked<T>(value, name(field), names_.code);
    }
    template <typename T>
    Checked<T> check_element(T value, Field field, std::size_t index) const {
        return Checked<T>(value, indexed(name(field), index), names_.code);
    }
    template <typename T>
    Checked<T> check_named(T value, const std::string& name) const {
        return Checked<T>(value, name, names_.code);
    }
    void check_finite(const Vec3& v, Field field) const {
        for (std::size_t k = 0; k < 3; ++k) check_element(v[k], field, k);
    }
    [[noreturn]] void fail(const std::string& name, const std::string& message) const {
        throw Error(names_.code, name + " " + message);
    }

    enum class Relation { below, at_most, at_least };
    void relate(double value, Field field, Relation relation, double factor, double other, Field other_field) const;

    void intestine(const IntestineConfig& intestine) const;
    void shape(const IntestineConfig& intestine) const;
    void solver(const SolverConfig& solver) const;
    void damping(const DampingConfig& damping) const;
    void mesentery(const MesenteryConfig& mesentery) const;
    void pinned(const PinnedConfig& pinned, std::size_t control_points) const;
    void clamped_tangents(const PinnedConfig& pinned, const double* start_points, std::size_t control_points) const;
    void collision(const CollisionConfig& collision, double radius) const;
    collision::Obstacle obstacle(const collision::Obstacle& obstacle, const std::string& name) const;
    void mesh(const collision::TriangleMesh& mesh, const std::string& name) const;
    Eigen::Quaterniond quaternion(const std::array<double, 4>& wxyz, const std::string& name) const;
    collision::ToolPose tool_pose(const collision::ToolPose& pose, const std::string& prefix) const;
    void tool_settings(const collision::ToolSettings& settings, const std::string& prefix) const;

private:
    bool given(Field field) const { return given_[static_cast<std::size_t>(field)]; }

    const FieldNames& names_;
    const FieldSet& given_;
};

// value (field) must be below / at most / at least factor x other (other_field). The
// message names what the caller wrote: when field still has its default but other_field
// was given, it is other_field that does not fit.
void Validator::relate(double value, Field field, Relation relation, double factor, double other,
                       Field other_field) const {
    const double bound = factor * other;
    const bool ok = relation == Relation::below     ? value < bound
                    : relation == Relation::at_most ? value <= bound
                                                    : value >= bound;
    if (ok) return;
    const char* op = relation == Relation::below ? "<" : relation == Relation::at_most ? "<=" : ">=";
    const std::string scaled = factor == 1.0 ? name(other_field) : format_number(factor) + " x " + name(other_field);
    if (!given(field) && given(other_field)) {
        std::string message = name(other_field) + " (" + format_number(other) + ") does not fit the default " +
                              name(field) + " (" + format_number(value) + "), which must be " + op + " " + scaled +
                              ": give " + name(field) + " too, or check " + name(other_field);
        if (const PlausibleRange* range = plausible_range(other_field)) {
            const std::string unlikely = implausibility(*range, other);
            if (!unlikely.empty()) message += ": " + unlikely;
        }
        throw Error(names_.code, message);
    }
    std::string bound_text = scaled + " (" + format_number(bound);
    if (!given(other_field))
        bound_text += factor == 1.0 ? ", the default" : ", from its default " + format_number(other);
    bound_text += ")";
    throw Error(names_.code, name(field) + " must be " + op + " " + bound_text + ", got " + format_number(value));
}

void Validator::intestine(const IntestineConfig& intestine) const {
    check(intestine.length, Field::length).above(0.0).at_most(kMaxLength);
    check(intestine.radius, Field::radius).above(0.0);
    relate(intestine.radius, Field::radius, Relation::below, 1.0, intestine.length, Field::length);
    check(intestine.control_points, Field::control_points)
        .at_least(spline::kMinControlPoints)
        .at_most(kMaxControlPoints);
    check(intestine.linear_density, Field::linear_density).above(0.0);
    check(intestine.stretch_stiffness, Field::stretch_stiffness).at_least(0.0);
    check(intestine.bend_stiffness, Field::bend_stiffness).at_least(0.0);
    shape(intestine);
}

// Only the fields of the chosen kind matter; the others are never read.
void Validator::shape(const IntestineConfig& intestine) const {
    const ShapeConfig& shape = intestine.shape;
    check(static_cast<int32_t>(shape.kind), Field::shape_kind)
        .at_least(static_cast<int32_t>(ShapeKind::line))
        .at_most(static_cast<int32_t>(ShapeKind::points));
    // Neighbouring legs or turns closer than a diameter would start interpenetrated.
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
            check(shape.leg_spacing, Field::shape_leg_spacing);
            relate(shape.leg_spacing, Field::shape_leg_spacing, Relation::at_least, 2.0, intestine.radius, Field::radius);
            break;
        case ShapeKind::helix:
            check_finite(shape.center, Field::shape_center);
            check(shape.helix_radius, Field::shape_helix_radius).above(0.0);
            check(shape.helix_pitch, Field::shape_helix_pitch);
            relate(shape.helix_pitch, Field::shape_helix_pitch, Relation::at_least, 2.0, intestine.radius, Field::radius);
            break;
        case ShapeKind::points: {
            const std::size_t n = intestine.control_points;
            const std::string points = name(Field::shape_points);
            if (shape.points.size() != 3 * n && names_.shape_points_nested) {
                fail(points, "must hold " + format_number(n) + " points (" + name(Field::control_points) +
                                 "), got " + format_number(shape.points.size() / 3));
            }
            if (shape.points.size() != 3 * n) {
                fail(points, "must hold " + format_number(3 * n) + " values (" + name(Field::control_points) +
                                 " x 3), got " + format_number(shape.points.size()));
            }
            for (std::size_t i = 0; i < shape.points.size(); ++i) {
                const std::string element = names_.shape_points_nested
                                                ? indexed(indexed(points, i / 3), i % 3)
                                                : indexed(points, i);
                check_named(shape.points[i], element);
            }
            break;
        }
    }
}

void Validator::solver(const SolverConfig& solver) const {
    check(static_cast<int32_t>(solver.integrator), Field::integrator)
        .at_least(static_cast<int32_t>(IntegratorKind::rk4))
        .at_most(static_cast<int32_t>(IntegratorKind::bdf2));
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
    check(pinned.clamped, Field::pinned_clamped).at_least(pin_none).at_most(pin_both);
    // The two clamps' constraints (mechanics/clamped_ends.h) must not share a control point.
    constexpr std::size_t kBothClampedPoints = 6;
    if (pinned.clamped == pin_both && control_points < kBothClampedPoints)
        fail(name(Field::pinned_clamped), "clamps both ends, which needs at least " +
                                              std::to_string(kBothClampedPoints) + " control points (" +
                                              name(Field::control_points) + " is " +
                                              std::to_string(control_points) + ")");
    for (std::size_t i = 0; i < pinned.points.size(); ++i) {
        const std::size_t point = pinned.points[i];
        check_element(point, Field::pinned_points, i).below(control_points, name(Field::control_points));
        const bool first = (pinned.clamped & pin_first) != 0 && (point == 1 || point == 2);
        const bool last = (pinned.clamped & pin_last) != 0 && (point + 2 == control_points || point + 3 == control_points);
        if (first || last)
            fail(indexed(name(Field::pinned_points), i),
                 "is " + std::to_string(point) + ", a control point whose motion the clamped " +
                     (first ? "first" : "last") + " end already constrains (" + name(Field::pinned_clamped) +
                     "): a point pin there would fight the clamp; remove it");
    }
}

void Validator::clamped_tangents(const PinnedConfig& pinned, const double* start_points,
                                 std::size_t control_points) const {
    for (const bool first : {true, false}) {
        if ((pinned.clamped & (first ? pin_first : pin_last)) == 0) continue;
        if (mechanics::clamped_end_is_degenerate(start_points, control_points, first))
            fail(name(Field::pinned_clamped),
                 std::string("clamps the ") + (first ? "first" : "last") +
                     " end, but the initial shape gives it no direction to hold: its tangent " +
                     (first ? "4 q1 - 3 q0 - q2" : "3 q[n-1] - 4 q[n-2] + q[n-3]") +
                     " is zero (the end folds back on itself); change the shape's " + (first ? "first" : "last") +
                     " three points");
    }
}

void Validator::collision(const CollisionConfig& collision, double radius) const {
    check(collision.sphere_spacing, Field::sphere_spacing).at_least(0.0);
    relate(collision.sphere_spacing, Field::sphere_spacing, Relation::at_most, 1.0, radius, Field::radius);
    check(collision.contact.stiffness, Field::contact_stiffness).at_least(0.0);
    check(collision.contact.damping, Field::contact_damping).at_least(0.0);
    check(collision.contact.friction, Field::contact_friction).at_least(0.0);
    check(collision.contact.slip_speed, Field::contact_slip_speed).above(0.0);
}

collision::Obstacle Validator::obstacle(const collision::Obstacle& o, const std::string& base) const {
    using collision::ObstacleKind;
    const auto field = [&](const char* key) { return base + "." + key; };
    check_named(static_cast<int32_t>(o.kind), field("kind"))
        .at_least(static_cast<int32_t>(ObstacleKind::box_inside))
        .at_most(static_cast<int32_t>(ObstacleKind::mesh));
    const auto finite = [&](const Vec3& v, const char* key) {
        for (std::size_t k = 0; k < 3; ++k) check_named(v[k], indexed(field(key), k));
    };
    switch (o.kind) {
        case ObstacleKind::box_inside:
            finite(o.center, "center");
            for (std::size_t k = 0; k < 3; ++k) check_named(o.extent[k], indexed(field("half_extents"), k)).above(0.0);
            break;
        case ObstacleKind::plane: {
            finite(o.center, "point");
            finite(o.extent, "normal");
            if (o.extent[0] == 0.0 && o.extent[1] == 0.0 && o.extent[2] == 0.0)
                fail(field("normal"), "must not be zero, got [0, 0, 0]");
            // Its length must be computable to normalise it.
            const double length2 = o.extent[0] * o.extent[0] + o.extent[1] * o.extent[1] + o.extent[2] * o.extent[2];
            if (!(length2 > 0.0) || !std::isfinite(length2))
                fail(field("normal"), "must have a length between 1e-150 and 1e150, got " + format(o.extent));
            break;
        }
        case ObstacleKind::sphere:
            finite(o.center, "center");
            check_named(o.radius, field("radius")).above(0.0);
            break;
        case ObstacleKind::capsule:
            finite(o.center, "start");
            finite(o.extent, "end");
            check_named(o.radius, field("radius")).above(0.0);
            break;
        case ObstacleKind::mesh:
            if (!o.mesh && !o.field) fail(field("mesh"), "must be given for a mesh obstacle");
            if (o.mesh) mesh(*o.mesh, base);
            check_named(o.voxel_size, field("voxel_size")).at_least(0.0);
            break;
    }
    // Every kind: its frame, and its friction (negative: the scene's).
    finite(o.pose.position, "position");
    check_named(o.friction, field("friction"));
    collision::Obstacle valid = o;
    const Eigen::Quaterniond& q = o.pose.orientation;
    valid.pose.orientation = quaternion({q.w(), q.x(), q.y(), q.z()}, field("orientation"));
    return valid;
}

void Validator::mesh(const collision::TriangleMesh& m, const std::string& base) const {
    const auto field = [&](const char* key) { return base + "." + key; };
    const std::size_t triangles = m.triangle_count();
    if (m.indices.size() % 3 != 0 || m.vertices.size() % 3 != 0)
        fail(field("mesh"), "must have 3 coordinates per vertex and 3 indices per triangle");
    if (triangles == 0) fail(field("mesh"), "must have at least one triangle, got 0");
    if (triangles > collision::kMaxMeshTriangles)
        fail(field("mesh"), "has " + std::to_string(triangles) + " triangles, more than the " +
                                std::to_string(collision::kMaxMeshTriangles) + " a mesh obstacle may have");
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
        if (!std::isfinite(m.vertices[i]))
            fail(field("vertices") + "[" + std::to_string(i / 3) + "]",
                 "must be finite, got " + format_number(m.vertices[i]) + " for coordinate " + std::to_string(i % 3));
    const std::size_t vertices = m.vertex_count();
    for (std::size_t i = 0; i < m.indices.size(); ++i)
        if (m.indices[i] >= vertices)
            fail(field("triangles") + "[" + std::to_string(i / 3) + "]",
                 "refers to vertex " + std::to_string(m.indices[i]) + ", but the mesh has " + std::to_string(vertices) +
                     " vertices (indices count from 0)");
    bool some_area = false;
    for (std::size_t t = 0; t < triangles && !some_area; ++t)
        some_area = (m.corner(t, 1) - m.corner(t, 0)).cross(m.corner(t, 2) - m.corner(t, 0)).squaredNorm() > 0.0;
    if (!some_area) fail(field("triangles"), "are all of zero area: nothing to collide with");
}

Eigen::Quaterniond Validator::quaternion(const std::array<double, 4>& q, const std::string& name) const {
    double norm2 = 0.0;
    for (std::size_t c = 0; c < 4; ++c) {
        check_named(q[c], indexed(name, c));
        norm2 += q[c] * q[c];
    }
    const double norm = std::sqrt(norm2);
    if (!(norm > 1e-12) || !std::isfinite(norm))
        fail(name, "must be a non-zero quaternion (w x y z), got one of norm " + format_number(norm));
    return Eigen::Quaterniond(q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm);
}

// Called at 1 kHz for every ent_tool_set_pose: names are made only for a message.
collision::ToolPose Validator::tool_pose(const collision::ToolPose& pose, const std::string& prefix) const {
    const ToolFieldNames& n = names_.tool;
    for (std::size_t c = 0; c < 3; ++c)
        if (!std::isfinite(pose.position[c])) check_named(pose.position[c], indexed(prefix + n.position, c));
    double norm2 = 0.0;
    for (std::size_t c = 0; c < 4; ++c) {
        if (!std::isfinite(pose.orientation[c])) check_named(pose.orientation[c], indexed(prefix + n.orientation, c));
        norm2 += pose.orientation[c] * pose.orientation[c];
    }
    const double norm = std::sqrt(norm2);
    if (!(norm > 1e-12) || !std::isfinite(norm))
        fail(prefix + n.orientation, "must be a non-zero quaternion (w x y z), got one of norm " + format_number(norm));
    collision::ToolPose unit = pose;
    for (double& c : unit.orientation) c /= norm;
    return unit;
}

void Validator::tool_settings(const collision::ToolSettings& s, const std::string& prefix) const {
    const ToolFieldNames& n = names_.tool;
    check_named(s.radius, prefix + n.radius).above(0.0).at_most(kMaxToolRadius);
    check_named(s.length, prefix + n.length).at_least(0.0).at_most(kMaxToolLength);
    check_named(s.max_force, prefix + n.max_force).above(0.0);
    check_named(s.grasp_margin, prefix + n.grasp_margin).at_least(0.0).at_most(kMaxToolRadius);
    check_named(s.grasp_stiffness, prefix + n.grasp_stiffness).above(0.0);
    check_named(s.grasp_damping, prefix + n.grasp_damping).at_least(0.0);
    check_named(static_cast<int32_t>(s.mode), prefix + n.mode)
        .at_least(static_cast<int32_t>(collision::ToolMode::proxy))
        .at_most(static_cast<int32_t>(collision::ToolMode::direct));
    check_named(s.coupling_stiffness, prefix + n.coupling_stiffness).above(0.0);
    check_named(s.coupling_damping, prefix + n.coupling_damping).at_least(0.0);
    check_named(s.friction, prefix + n.friction);  // finite; < 0: the scene's
}

FieldNames make_field_names(ErrorCode code, bool shape_points_nested, const ToolFieldNames& tool,
                            std::initializer_list<std::pair<Field, const char*>> entries) {
    FieldNames names{code, shape_points_nested, {}, tool};
    for (const auto& [field, name] : entries) names.names[static_cast<std::size_t>(field)] = name;
    return names;
}

}  // namespace

const FieldNames& json_field_names() {
    static const FieldNames names = make_field_names(
        ErrorCode::invalid_scene, true,
        {"radius", "length", "max_force", "grasp_margin", "grasp_stiffness", "grasp_damping", "position",
         "orientation", "mode", "coupling_stiffness", "coupling_damping", "friction"},
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
            {Field::pinned_clamped, "pinned.clamped"},
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
        {"radius_m", "length_m", "max_force_N", "grasp_margin_m", "grasp_stiffness_N_per_m",
         "grasp_damping_N_s_per_m", "position_m", "orientation_wxyz", "mode", "coupling_stiffness_N_per_m",
         "coupling_damping_N_s_per_m", "friction"},
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
            {Field::pinned_clamped, "clamped_ends"},
            {Field::sphere_spacing, "collision_sphere_spacing_m"},
            {Field::contact_stiffness, "contact_stiffness_N_per_m"},
            {Field::contact_damping, "contact_damping_N_s_per_m"},
            {Field::contact_friction, "contact_friction"},
            {Field::contact_slip_speed, "contact_slip_speed_m_per_s"},
            {Field::obstacle, "obstacle"},
        });
    return names;
}

SceneConfig validate(SceneConfig config, const FieldNames& names, const FieldSet& given) {
    const Validator validator(names, given);
    // A points shape starts at rest: its length 0 (JSON: no length) is the length of the
    // spline through the points (points_length.h), once they are seen to be valid.
    if (config.intestine.shape.kind == ShapeKind::points && config.intestine.length == kLengthOfThePoints) {
        IntestineConfig placeholder = config.intestine;
        placeholder.length = IntestineConfig().length;
        validator.intestine(placeholder);
        config.intestine.length = points_spline_length(config);
        if (!(config.intestine.length > config.intestine.radius))
            validator.fail(names[Field::shape_points],
                           "must spread along the bowel: the spline through them is " +
                               format_number(config.intestine.length) + " m long, not longer than " +
                               names[Field::radius] + " (" + format_number(config.intestine.radius) +
                               " m), and a points shape without a length takes the spline's");
    }
    validator.intestine(config.intestine);
    validator.solver(config.solver);
    if (config.gravity) validator.check_finite(*config.gravity, Field::gravity);
    if (config.damping) validator.damping(*config.damping);
    if (config.mesentery) validator.mesentery(*config.mesentery);
    if (config.pinned) validator.pinned(*config.pinned, config.intestine.control_points);
    validator.collision(config.collision, config.intestine.radius);
    for (std::size_t i = 0; i < config.environment.size(); ++i)
        config.environment[i] = validator.obstacle(config.environment[i], indexed(names[Field::obstacle], i));
    // What follows an obstacle must name one.
    const std::size_t obstacles = config.environment.size();
    if (config.pinned)
        for (std::size_t i = 0; i < config.pinned->attached.size(); ++i) {
            const PinAttachment& pin = config.pinned->attached[i];
            // Only JSON attaches pins in the description (C pins with ent_scene_pin_point).
            const std::string name = indexed("pinned.attached", i);
            validator.check_named(std::size_t{pin.point}, name + ".control_point")
                .below(config.intestine.control_points, names[Field::control_points]);
            validator.check_named(pin.obstacle, name + ".obstacle").below(obstacles, "the number of obstacles");
            // A clamped end's point moves with its clamp: pinned alone, the clamp would be
            // half attached (the end point on the organ, its direction in the world).
            for (const bool first : {true, false})
                if ((config.pinned->clamped & (first ? pin_first : pin_last)) != 0 &&
                    pin.point == (first ? 0 : config.intestine.control_points - 1))
                    validator.fail(name + ".control_point",
                                   "is " + std::to_string(pin.point) + ", the point of the clamped " +
                                       (first ? "first" : "last") +
                                       " end (pinned.clamped): attach the clamped end with pinned.clamped_attached");
        }
    if (config.mesentery && config.mesentery->obstacle)
        validator.check_named(*config.mesentery->obstacle, "mesentery.obstacle")
            .below(obstacles, "the number of obstacles");
    if (config.pinned)
        for (const bool first : {true, false}) {
            const std::optional<std::size_t>& obstacle = config.pinned->clamped_obstacle[first ? 0 : 1];
            if (!obstacle) continue;
            const std::string name = std::string("pinned.clamped_attached.") + (first ? "first" : "last");
            if ((config.pinned->clamped & (first ? pin_first : pin_last)) == 0)
                validator.fail(name, std::string("attaches the ") + (first ? "first" : "last") +
                                         " end, which pinned.clamped does not clamp: clamp it or remove the key");
            validator.check_named(*obstacle, name).below(obstacles, "the number of obstacles");
        }
    for (std::size_t i = 0; i < config.tools.size(); ++i) {
        const std::string prefix = indexed("tools", i) + ".";
        validator.tool_settings(config.tools[i].settings, prefix);
        config.tools[i].pose = validator.tool_pose(config.tools[i].pose, prefix);
    }

    const std::size_t n = config.intestine.control_points;
    config.start_points.assign(3 * n, 0.0);
    build_shape(config.intestine.shape, config.intestine.length, n, config.start_points.data());
    if (config.pinned) validator.clamped_tangents(*config.pinned, config.start_points.data(), n);
    const StartClearance clearance = start_clearance(config);
    // A mesh is checked by the scene, once its distance field is built.
    for (std::size_t i = 0; i < config.environment.size(); ++i)
        if (config.environment[i].kind != collision::ObstacleKind::mesh)
            check_clearance(config.environment[i], indexed(names[Field::obstacle], i), names.code,
                            config.start_points.data(), n, clearance);
    return config;
}

StartClearance start_clearance(const SceneConfig& config) {
    const double radius = config.intestine.radius;
    const double spacing = config.collision.sphere_spacing > 0.0 ? config.collision.sphere_spacing : 0.5 * radius;
    const double sphere_mass = config.intestine.linear_density * spacing;
    return {radius, std::sqrt(config.collision.contact.stiffness / sphere_mass), config.solver.max_speed};
}

FieldSet fields_apart_from_defaults(const SceneConfig& config) {
    const SceneConfig defaults;
    FieldSet apart;
    const auto mark = [&](Field field, bool differs) { apart[static_cast<std::size_t>(field)] = differs; };
    mark(Field::length, config.intestine.length != defaults.intestine.length);
    mark(Field::radius, config.intestine.radius != defaults.intestine.radius);
    mark(Field::control_points, config.intestine.control_points != defaults.intestine.control_points);
    mark(Field::shape_leg_spacing, config.intestine.shape.leg_spacing != defaults.intestine.shape.leg_spacing);
    mark(Field::shape_helix_pitch, config.intestine.shape.helix_pitch != defaults.intestine.shape.helix_pitch);
    mark(Field::sphere_spacing, config.collision.sphere_spacing != defaults.collision.sphere_spacing);
    return apart;
}

collision::Obstacle validate_obstacle(const collision::Obstacle& obstacle, const std::string& name,
                                     const FieldNames& names, const double* control_points, std::size_t count,
                                     const StartClearance* clearance) {
    const FieldSet all = FieldSet().set();
    collision::Obstacle valid = Validator(names, all).obstacle(obstacle, name);
    const bool unprepared_mesh = valid.kind == collision::ObstacleKind::mesh && !valid.field;
    if (control_points != nullptr && clearance != nullptr && !unprepared_mesh)
        check_clearance(valid, name, names.code, control_points, count, *clearance);
    return valid;
}

collision::ToolConfig validate_tool(const collision::ToolConfig& tool, const std::string& prefix,
                                    const FieldNames& names) {
    const FieldSet all = FieldSet().set();
    const Validator validator(names, all);
    validator.tool_settings(tool.settings, prefix);
    collision::ToolConfig valid = tool;
    valid.pose = validator.tool_pose(tool.pose, prefix);
    return valid;
}

collision::ToolPose validate_tool_pose(const collision::ToolPose& pose, const std::string& prefix,
                                       const FieldNames& names) {
    const FieldSet all = FieldSet().set();
    return Validator(names, all).tool_pose(pose, prefix);
}

}  // namespace enteron::scene
