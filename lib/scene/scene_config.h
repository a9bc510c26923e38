// SPDX-License-Identifier: Apache-2.0
// A scene description in C++ terms, whatever it came from (the C struct or JSON v1), and
// the one home of its defaults: the JSON loader starts from a default SceneConfig and
// ent_scene_desc_default fills the C struct from one. An effect that the description does
// not name is an empty optional (or a zero stiffness) here, and is then never built.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "base/geometry.h"
#include "collision/contact_model.h"
#include "collision/obstacle.h"
#include "collision/tool.h"
#include "mechanics/integrator_kind.h"
#include "spline/catmull_rom.h"

namespace enteron::scene {

enum class ShapeKind : int32_t { line = 0, serpentine = 1, helix = 2, points = 3 };
using mechanics::IntegratorKind;

struct ShapeConfig {
    ShapeKind kind = ShapeKind::helix;
    Vec3 center{0.0, 0.0, 0.0};     // m
    Vec3 direction{1.0, 0.0, 0.0};  // line only; normalised when built
    double leg_length = 0.3;        // serpentine, m
    double leg_spacing = 0.05;      // serpentine, m
    double helix_radius = 0.1;      // m
    double helix_pitch = 0.03;      // m per turn
    std::vector<double> points;     // points only: control_points x 3, m
};

struct IntestineConfig {
    double length = 6.0;             // m
    double radius = 0.0125;          // m
    std::size_t control_points = 240;
    double linear_density = 0.3;     // kg/m
    // The bowel is elastic unless told otherwise; 0 turns the effect off (it is not built).
    double stretch_stiffness = 100.0;  // EA, N: the stretch effect
    double bend_stiffness = 2.5e-3;    // EI, N m^2: the bend effect
    ShapeConfig shape;
    // Properties along the length, each in place of its constant above: pairs s_0, value_0,
    // s_1, value_1, ... (s the arc length from the first end at rest, m, increasing, from 0
    // to the length; piecewise linear between them; spline/length_profile.h). Empty: the
    // constant. validate() sets each constant to its profile's largest value.
    std::vector<double> radius_profile;             // m
    std::vector<double> linear_density_profile;     // kg/m
    std::vector<double> stretch_stiffness_profile;  // N
    std::vector<double> bend_stiffness_profile;     // N m^2
};

struct SolverConfig {
    IntegratorKind integrator = IntegratorKind::implicit_euler;
    double timestep = 1e-3;          // s
    std::size_t max_substeps = 1000;
    std::size_t max_subdivisions = 4;
    double max_speed = 50.0;         // m/s
};

struct DampingConfig {
    double drag = 0.05;     // N s / m^2
    double stretch = 0.05;  // N s
    double bend = 0.0;      // N m^2 s
};

struct MesenteryConfig {
    Vec3 root_start{-0.075, 0.0, 0.0};  // m
    Vec3 root_end{0.075, 0.0, 0.0};     // m
    std::size_t attachments = 60;
    double stiffness = 5.0;             // N/m per spring
    double rest_length = 0.0;           // m; 0: each spring's initial length
    std::optional<std::size_t> obstacle;  // the root follows this obstacle's frame
    // The root as a polyline (JSON root, C mesentery_root_points_m): x, y, z of two or more
    // points, m, in place of root_start and root_end. validate() makes one of two points the
    // segment root_start, root_end (and empties this), and sets those two to the ends of a
    // longer one, so that a reader of the segment sees where the root starts and ends.
    std::vector<double> root_points;
    // Where along the root each point of the bowel is tied: pairs s_0, t_0, s_1, t_1, ...
    // (s on the bowel, m at rest from its first end, increasing; t the fraction of the root's
    // length, 0..1, not decreasing); empty: the same fraction of the lengths.
    std::vector<double> root_mapping;
};

enum PinnedEnds : int32_t { pin_none = 0, pin_first = 1, pin_last = 2, pin_both = 3 };

// A control point held on an obstacle's frame, moving with it.
struct PinAttachment {
    uint32_t point = 0;
    std::size_t obstacle = 0;
};

// A span of the bowel held in place: every control point whose rest arc length (from the
// first end) lies in [from, to] is pinned, in the world or on an obstacle's frame (the
// retroperitoneal colon on the posterior wall). scene/pin_spans.h finds them.
struct PinSpan {
    double from = 0.0;  // m
    double to = 0.0;    // m
    std::optional<std::size_t> obstacle;
};

struct PinnedConfig {
    int32_t ends = pin_none;
    std::vector<uint32_t> points;  // further control point indices
    std::vector<PinAttachment> attached;  // points held on obstacles (JSON pinned.attached)
    int32_t clamped = pin_none;    // ends held in place and in direction (mechanics/clamped_ends.h)
    // The obstacle the first / last clamped end follows (JSON pinned.clamped_attached).
    std::optional<std::size_t> clamped_obstacle[2] = {};
    std::vector<PinSpan> spans = {};  // spans of the bowel pinned (JSON pinned.spans)
};

// Settings shared by every contact of the bowel: the environment, the self-contact and
// the tools use the same spheres and law.
struct CollisionConfig {
    double sphere_spacing = 0.0;  // m at rest; 0: radius / 2
    collision::ContactParameters contact;
};

// The collision spheres' spacing at rest, m, for a tube of radius R: the description's, or
// R / 2 when it leaves it at 0.
inline double resting_sphere_spacing(const CollisionConfig& collision, double radius) {
    return collision.sphere_spacing > 0.0 ? collision.sphere_spacing : 0.5 * radius;
}

// An obstacle of each kind as a JSON entry or ent_obstacle_desc_default starts: a cavity
// 24 cm wide around the origin, a floor through the origin, organs of 5 cm radius.
inline collision::Obstacle default_obstacle(collision::ObstacleKind kind) {
    collision::Obstacle obstacle;
    obstacle.kind = kind;
    switch (kind) {
        case collision::ObstacleKind::box_inside: obstacle.extent = {0.12, 0.12, 0.12}; break;
        case collision::ObstacleKind::plane: obstacle.extent = {0.0, 0.0, 1.0}; break;
        case collision::ObstacleKind::sphere: obstacle.radius = 0.05; break;
        case collision::ObstacleKind::capsule:
            obstacle.extent = {0.0, 0.0, 0.1};
            obstacle.radius = 0.05;
            break;
        case collision::ObstacleKind::mesh: break;
    }
    return obstacle;
}

// Gravity at the Earth's surface, m/s^2: what ent_scene_desc_default turns on.
inline const Vec3 kStandardGravity{0.0, 0.0, -9.81};

struct SceneConfig {
    IntestineConfig intestine;
    SolverConfig solver;
    std::optional<Vec3> gravity;  // m/s^2
    std::optional<DampingConfig> damping;
    std::optional<MesenteryConfig> mesentery;
    std::optional<PinnedConfig> pinned;
    CollisionConfig collision;
    std::vector<collision::Obstacle> environment;  // empty: the environment effect is off
    std::vector<collision::ToolConfig> tools;       // empty: the tools effect is off
    bool self_collision = false;                   // folds that touch push apart

    // Set by validate(): the initial control points of the shape (control_points x 3, m).
    std::vector<double> start_points;
};

// How the axis' spline continues past its ends: quadratic at a clamped end
// (mechanics/clamped_ends.h), linear otherwise. The mechanics and every reader of the axis
// use the same.
inline spline::Ends spline_ends(const SceneConfig& config) {
    const int32_t clamped = config.pinned ? config.pinned->clamped : pin_none;
    spline::Ends ends;
    if (clamped & pin_first) ends.first = spline::EndTreatment::quadratic;
    if (clamped & pin_last) ends.last = spline::EndTreatment::quadratic;
    return ends;
}

}  // namespace enteron::scene
