// SPDX-License-Identifier: Apache-2.0
#include "scene/plausible_ranges.h"

#include <cmath>

#include "scene/checked_value.h"
#include "scene/points_length.h"

namespace enteron::scene {

namespace {

constexpr UnitSlip kMillimetres{1e3, "millimetres"};
constexpr UnitSlip kCentimetres{1e2, "centimetres"};
constexpr UnitSlip kNone{0.0, nullptr};

// Generous bounds: a value outside is far from anything a human abdomen has.
constexpr PlausibleRange kLength{"a human small bowel's length", 0.05, 10.0, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kRadius{"a human small bowel's radius", 0.004, 0.03, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kLinearDensity{"a human small bowel's mass per metre", 0.05, 2.0, "kg/m",
                                        {{1e3, "g/m (or is it a density in kg/m^3?)"}, kNone}};
constexpr PlausibleRange kStretchStiffness{"a human small bowel's axial stiffness EA", 1.0, 1e4, "N", {kNone, kNone}};
constexpr PlausibleRange kBendStiffness{"a human small bowel's bending stiffness EI", 1e-6, 0.1, "N m^2",
                                        {kNone, kNone}};
constexpr PlausibleRange kShapeSize{"an abdominal cavity's size", 0.005, 1.0, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kGravity{"the Earth's gravity (9.81 m/s^2; 0 turns it off)", 5.0, 20.0, "m/s^2",
                                  {{1e3, "mm/s^2"}, {1.0 / 9.81, "g"}}};
constexpr PlausibleRange kTimestep{"a real-time substep", 1e-6, 0.01, "s", {{1e3, "milliseconds"}, kNone}};
constexpr PlausibleRange kDrag{"the drag of a bowel in the abdomen", 0.0, 10.0, "N s/m^2", {kNone, kNone}};
constexpr PlausibleRange kAxialDamping{"a bowel's internal damping", 0.0, 10.0, "N s", {kNone, kNone}};
constexpr PlausibleRange kMesenteryStiffness{"a mesentery spring's stiffness", 0.01, 1e3, "N/m", {{1e3, "N/mm"}, kNone}};
constexpr PlausibleRange kContactStiffness{"a soft-tissue contact's stiffness", 10.0, 1e5, "N/m",
                                           {{1e3, "N/mm"}, kNone}};
constexpr PlausibleRange kContactDamping{"a soft-tissue contact's damping", 0.0, 100.0, "N s/m", {kNone, kNone}};
constexpr PlausibleRange kFriction{"a friction coefficient of wet tissue", 0.0, 2.0, "", {kNone, kNone}};
constexpr PlausibleRange kCavityHalfSize{"an abdominal cavity's half size", 0.02, 1.0, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kOrganRadius{"an abdominal organ's or vessel's radius", 0.002, 0.5, "m",
                                      {kMillimetres, kCentimetres}};
constexpr PlausibleRange kToolRadius{"a laparoscopic tool's radius", 0.001, 0.02, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kToolLength{"a laparoscopic tool's shaft", 0.0, 1.0, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kToolForce{"a force a haptic device renders", 0.01, 100.0, "N", {kNone, kNone}};

bool within(const PlausibleRange& range, double value) { return value >= range.low && value <= range.high; }

std::string with_unit(double value, const char* unit) {
    return format_number(value) + (unit[0] != '\0' ? std::string(" ") + unit : std::string());
}

void warn(const Logger& logger, const std::string& name, const PlausibleRange& range, double value) {
    const std::string unlikely = implausibility(range, value);
    if (!unlikely.empty()) logger.log(LogLevel::warning, "%s: %s", name.c_str(), unlikely.c_str());
}

}  // namespace

std::string implausibility(const PlausibleRange& range, double value) {
    if (!std::isfinite(value) || within(range, value)) return {};
    std::string text = with_unit(value, range.unit) + " is far " + (value > range.high ? "above " : "below ") +
                       range.what + " (" + format_number(range.low) + " to " + with_unit(range.high, range.unit) + ")";
    for (const UnitSlip& slip : range.slips) {
        if (slip.unit != nullptr && within(range, value / slip.factor))
            return text + ": was it given in " + slip.unit + "?";
    }
    return text;
}

const PlausibleRange* plausible_range(Field field) {
    switch (field) {
        case Field::length: return &kLength;
        case Field::radius: return &kRadius;
        case Field::linear_density: return &kLinearDensity;
        case Field::stretch_stiffness: return &kStretchStiffness;
        case Field::bend_stiffness: return &kBendStiffness;
        case Field::shape_leg_length:
        case Field::shape_leg_spacing:
        case Field::shape_helix_radius:
        case Field::shape_helix_pitch: return &kShapeSize;
        case Field::timestep: return &kTimestep;
        case Field::drag: return &kDrag;
        case Field::stretch_damping:
        case Field::bend_damping: return &kAxialDamping;
        case Field::mesentery_stiffness: return &kMesenteryStiffness;
        case Field::contact_stiffness: return &kContactStiffness;
        case Field::contact_damping: return &kContactDamping;
        case Field::contact_friction: return &kFriction;
        default: return nullptr;
    }
}

void warn_implausible(const SceneConfig& config, const FieldNames& names, const Logger& logger) {
    if (!logger.enabled()) return;
    const auto check = [&](Field field, double value) {
        if (const PlausibleRange* range = plausible_range(field)) warn(logger, names[field], *range, value);
    };
    const IntestineConfig& intestine = config.intestine;
    check(Field::length, intestine.length);
    warn_points_length(config, names, logger);
    check(Field::radius, intestine.radius);
    check(Field::linear_density, intestine.linear_density);
    // 0 turns an elasticity off: a choice, not a mistake.
    if (intestine.stretch_stiffness != 0.0) check(Field::stretch_stiffness, intestine.stretch_stiffness);
    if (intestine.bend_stiffness != 0.0) check(Field::bend_stiffness, intestine.bend_stiffness);
    switch (intestine.shape.kind) {
        case ShapeKind::serpentine:
            check(Field::shape_leg_length, intestine.shape.leg_length);
            check(Field::shape_leg_spacing, intestine.shape.leg_spacing);
            break;
        case ShapeKind::helix:
            check(Field::shape_helix_radius, intestine.shape.helix_radius);
            check(Field::shape_helix_pitch, intestine.shape.helix_pitch);
            break;
        default: break;
    }
    check(Field::timestep, config.solver.timestep);
    if (config.gravity) {
        const Vec3& g = *config.gravity;
        const double magnitude = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (magnitude != 0.0) warn(logger, "|" + std::string(names[Field::gravity]) + "|", kGravity, magnitude);
    }
    if (config.damping) {
        check(Field::drag, config.damping->drag);
        check(Field::stretch_damping, config.damping->stretch);
        check(Field::bend_damping, config.damping->bend);
    }
    if (config.mesentery) check(Field::mesentery_stiffness, config.mesentery->stiffness);
    // The contact law matters only to a scene that has contacts.
    if (config.self_collision || !config.environment.empty() || !config.tools.empty()) {
        check(Field::contact_stiffness, config.collision.contact.stiffness);
        check(Field::contact_damping, config.collision.contact.damping);
        check(Field::contact_friction, config.collision.contact.friction);
    }
    for (std::size_t i = 0; i < config.environment.size(); ++i)
        warn_implausible(config.environment[i], names[Field::obstacle] + ("[" + std::to_string(i) + "]"), logger);
    for (std::size_t i = 0; i < config.tools.size(); ++i)
        warn_implausible(config.tools[i].settings, "tools[" + std::to_string(i) + "].", names, logger);
}

void warn_implausible(const collision::Obstacle& obstacle, const std::string& name, const Logger& logger) {
    if (!logger.enabled()) return;
    using collision::ObstacleKind;
    switch (obstacle.kind) {
        case ObstacleKind::box_inside:
            for (std::size_t k = 0; k < 3; ++k)
                warn(logger, name + ".half_extents[" + std::to_string(k) + "]", kCavityHalfSize, obstacle.extent[k]);
            break;
        case ObstacleKind::sphere:
        case ObstacleKind::capsule: warn(logger, name + ".radius", kOrganRadius, obstacle.radius); break;
        case ObstacleKind::plane: break;
        case ObstacleKind::mesh: {
            // A mesh in millimetres (a CT export) is a thousand times too large.
            const collision::TriangleMesh* mesh = obstacle.mesh ? obstacle.mesh.get() : nullptr;
            if (mesh == nullptr || mesh->vertex_count() == 0) break;
            Vec3 low = mesh->vertex(0), high = low;
            for (std::size_t v = 1; v < mesh->vertex_count(); ++v) {
                low = low.cwiseMin(mesh->vertex(v));
                high = high.cwiseMax(mesh->vertex(v));
            }
            warn(logger, name + " (mesh) half of its largest side", kCavityHalfSize, 0.5 * (high - low).maxCoeff());
            break;
        }
    }
}

void warn_implausible(const collision::ToolSettings& tool, const std::string& prefix, const FieldNames& names,
                      const Logger& logger) {
    if (!logger.enabled()) return;
    warn(logger, prefix + names.tool.radius, kToolRadius, tool.radius);
    warn(logger, prefix + names.tool.length, kToolLength, tool.length);
    warn(logger, prefix + names.tool.max_force, kToolForce, tool.max_force);
}

}  // namespace enteron::scene
