// SPDX-License-Identifier: Apache-2.0
// The hard cases. Each builds its scene through the public C API (JSON, or ent_scene_desc
// where the control points are computed) and states its bounds; stability_run.cpp checks them.
//
// Energy: without tools nothing outside the bowel does work on it (gravity, the mesentery,
// the contacts and the pins are conservative or fixed; damping and friction only take energy
// away), so the total energy must not rise above its initial value. The allowance covers
// the integrators' own energy error, which for the explicit ones oscillates with the
// substep. Penetration bounds are what each case can honestly promise (see each case).
#include "hard_cases.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tool_drivers.h"

namespace stability {

namespace {

constexpr double kRadius = 0.0125;  // m, the default tube radius R

ent_scene* from_json(const std::string& json) {
    ent_scene* scene = nullptr;
    return ent_scene_create_json(json.data(), json.size(), &scene) == ENT_OK ? scene : nullptr;
}

ent_scene* from_desc(const ent_scene_desc& desc) {
    ent_scene* scene = nullptr;
    return ent_scene_create(&desc, &scene) == ENT_OK ? scene : nullptr;
}

ent_scene_desc base_desc(int32_t integrator, uint32_t control_points, double length_m) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.integrator = integrator;
    desc.control_points = control_points;
    desc.length_m = length_m;
    return desc;
}

// Adds an obstacle to a scene just made; on failure destroys it. nullptr in, nullptr out.
ent_scene* add_or_destroy(ent_scene* scene, const ent_obstacle_desc& obstacle) {
    if (scene != nullptr && ent_scene_add_obstacle(scene, &obstacle, nullptr) != ENT_OK) {
        ent_scene_destroy(scene);
        return nullptr;
    }
    return scene;
}

// The 6 m bowel of the demo: 240 control points, gravity, damping, hung from its mesentery.
// With `contacts` it lies in a 30 cm abdominal cavity and its folds collide with each other,
// as in the demo. Without, it only hangs: the scene of the cases that need an explicit
// integrator (contacts bound their stable substep to a few microseconds through the
// friction's damping, so a contact scene costs hundreds of substeps per millisecond with
// rk4 or symplectic Euler).
std::string demo_bowel(const std::string& integrator, double timestep_s, double stretch_stiffness_N, bool contacts,
                       const std::string& tools = "") {
    return R"({
  "intestine": {"length": 6.0, "radius": 0.0125, "control_points": 240, "linear_density": 0.3,
                "stretch_stiffness": )" + std::to_string(stretch_stiffness_N) + R"(, "bend_stiffness": 2.5e-3,
                "shape": {"kind": "helix", "center": [0, 0, -0.13], "helix_radius": 0.1, "helix_pitch": 0.025}},
  "solver": {"integrator": ")" + integrator + R"(", "timestep": )" + std::to_string(timestep_s) + R"(},
  "gravity": [0, 0, -9.81],
  "damping": {},)" + (contacts ? R"(
  "environment": [{"type": "box_inside", "center": [0, 0, 0], "half_extents": [0.15, 0.15, 0.15]}],
  "self_collision": {},)" : "") + tools + R"(
  "mesentery": {"root": [[-0.075, 0, 0], [0.075, 0, 0]], "stiffness": 5, "attachments": 60}
})";
}

// The 6 m bowel, no mesentery, dropped as a tall narrow helix (radius 4 cm, 24 turns, 60 cm
// high) into an open-top cube of 12 cm: the floor and four walls as planes, so the bowel
// piles above the rim as it must (its 2.9 L do not fit in the cube's 1.7 L).
std::string dropped_bowel(const std::string& integrator, const std::string& tools = "") {
    return R"({
  "intestine": {"length": 6.0, "radius": 0.0125, "control_points": 240, "linear_density": 0.3,
                "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                "shape": {"kind": "helix", "center": [0, 0, -0.0475], "helix_radius": 0.04, "helix_pitch": 0.025}},
  "solver": {"integrator": ")" + integrator + R"(", "timestep": 0.001},
  "gravity": [0, 0, -9.81],
  "damping": {},
  "environment": [
    {"type": "plane", "point": [0, 0, -0.06], "normal": [0, 0, 1]},
    {"type": "plane", "point": [-0.06, 0, 0], "normal": [1, 0, 0]},
    {"type": "plane", "point": [0.06, 0, 0], "normal": [-1, 0, 0]},
    {"type": "plane", "point": [0, -0.06, 0], "normal": [0, 1, 0]},
    {"type": "plane", "point": [0, 0.06, 0], "normal": [0, -1, 0]}],)" + tools + R"(
  "self_collision": {}
})";
}

// n points spaced evenly in arc length along a polyline (which must be long enough).
std::vector<double> resample(const std::vector<double>& polyline, uint32_t n, double length) {
    std::vector<double> points(3 * n);
    const double step = length / (n - 1);
    std::size_t k = 0;      // segment [k, k + 1] of the polyline
    double walked = 0.0;    // arc length at vertex k
    for (uint32_t i = 0; i < n; ++i) {
        const double s = step * i;
        for (;;) {
            const double* a = &polyline[3 * k];
            const double* b = &polyline[3 * k + 3];
            const double segment = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                                             (b[2] - a[2]) * (b[2] - a[2]));
            if (s <= walked + segment || 3 * (k + 2) >= polyline.size()) {
                const double t = segment > 0.0 ? std::min(1.0, (s - walked) / segment) : 0.0;
                for (int c = 0; c < 3; ++c) points[3 * i + c] = a[c] + t * (b[c] - a[c]);
                break;
            }
            walked += segment;
            ++k;
        }
    }
    return points;
}

// The 6 m bowel packed into a closed 12 cm cube from the start: its axis runs back and forth
// in 8 layers of 8 legs, 13.6 mm apart, every centre inside the cube by R. Its 2.9 L cannot
// fit in the cube's 1.7 L, so neighbouring legs overlap by 11.4 mm (0.9 R) at the start and
// must keep overlapping: the contacts and the walls hold a compressed pile.
ent_scene* packed_in_closed_cube(int32_t integrator) {
    constexpr double half = 0.06, inner = half - kRadius;
    constexpr int legs = 8;
    constexpr double spacing = 2.0 * inner / (legs - 1);
    std::vector<double> polyline;
    for (int layer = 0; layer < legs; ++layer) {
        for (int leg = 0; leg < legs; ++leg) {
            const int row = layer % 2 == 0 ? leg : legs - 1 - leg;  // back along y on odd layers
            const bool forward = (layer * legs + leg) % 2 == 0;
            const double y = -inner + spacing * row, z = -inner + spacing * layer;
            polyline.insert(polyline.end(), {forward ? -inner : inner, y, z, forward ? inner : -inner, y, z});
        }
    }
    const std::vector<double> points = resample(polyline, 240, 6.0);
    ent_scene_desc desc = base_desc(integrator, 240, 6.0);
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    desc.shape = ENT_SHAPE_POINTS;
    desc.shape_points_xyz_m = points.data();
    ent_scene* scene = from_desc(desc);
    ent_obstacle_desc cube;
    ent_obstacle_desc_default(&cube);
    cube.kind = ENT_OBSTACLE_BOX_INSIDE;
    for (double& h : cube.half_extents_m) h = half;
    return add_or_destroy(scene, cube);
}


// A 6 m bowel on a straight line 30 % longer than its rest length, both ends held, sagging
// under gravity: every segment starts 30 % over-stretched (27 J of stretch energy).
ent_scene* overstretched(int32_t integrator) {
    constexpr uint32_t n = 240;
    constexpr double length = 6.0, stretch = 1.3;
    std::vector<double> points(3 * n, 0.0);
    for (uint32_t i = 0; i < n; ++i) points[3 * i] = stretch * length * (double(i) / (n - 1) - 0.5);
    ent_scene_desc desc = base_desc(integrator, n, length);
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.pinned_ends = ENT_PIN_BOTH;
    desc.shape = ENT_SHAPE_POINTS;
    desc.shape_points_xyz_m = points.data();
    return from_desc(desc);
}

// A 1 m bowel of 40 control points whose initial polygon has every degeneracy at once:
// three points on top of a fourth (zero-length segments), a straight run that folds back
// onto itself along the same line (collinear, and with `contacts` the collision spheres of
// the two legs coincide), and two more coincident points near the end. With `contacts` it
// lies on a floor and its folds collide; without, its first end is held and it swings
// (explicit integrators: see demo_bowel).
ent_scene* degenerate(int32_t integrator, bool contacts) {
    constexpr uint32_t n = 40;
    constexpr double chord = 1.0 / (n - 1);
    std::vector<double> points(3 * n, 0.0);
    double x = 0.0;
    for (uint32_t i = 1; i < n; ++i) {
        const bool coincident = (i >= 5 && i <= 7) || i == 31;  // with the point before
        const bool back = i >= 14 && i <= 20;                   // over points 13 .. 7
        x += coincident ? 0.0 : back ? -chord : chord;
        points[3 * i] = x;
    }
    for (uint32_t i = 0; i < n; ++i) points[3 * i + 2] = kRadius;  // on the floor z = 0
    ent_scene_desc desc = base_desc(integrator, n, 1.0);
    desc.shape = ENT_SHAPE_POINTS;
    desc.shape_points_xyz_m = points.data();
    if (!contacts) {
        desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
        desc.pinned_ends = ENT_PIN_FIRST;
        return from_desc(desc);
    }
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    ent_obstacle_desc floor;
    ent_obstacle_desc_default(&floor);
    floor.kind = ENT_OBSTACLE_PLANE;  // z = 0, normal +z
    return add_or_destroy(from_desc(desc), floor);
}

// Every control point at the same place: the axis has zero length and 30 J of compressed
// stretch energy. The first end is held, so the bowel unfolds hanging from it. Without
// contacts: with self-contact, the collision spheres of a zero-length axis all count as
// neighbours until round-off gives the axis some length, then all collide 2R deep at once
// and every later step is refused (ENT_ERROR_UNSTABLE, state unchanged; see docs/stability.md).
ent_scene* collapsed(int32_t integrator) {
    constexpr uint32_t n = 24;
    std::vector<double> points(3 * n, 0.0);
    ent_scene_desc desc = base_desc(integrator, n, 0.6);
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.pinned_ends = ENT_PIN_FIRST;
    desc.shape = ENT_SHAPE_POINTS;
    desc.shape_points_xyz_m = points.data();
    return from_desc(desc);
}

// Bounds. Energy: the allowance is 1 mJ (the kinetic energy of the 1.8 kg bowel at 3 cm/s)
// unless the case says why it needs more. Penetration: R / 2 where contacts settle (a
// pile's weight on penalty springs), R where a 50 ms step lets a sphere travel 2R into a
// contact before the next evaluation, and 2R (two sphere centres on top of each other; a
// wall can push deeper) where the geometry forbids better: the closed cube cannot hold the
// bowel's volume, and a fold of zero radius keeps the pair at the edge of the neighbour
// window (pi R along the axis) almost on top of each other.
// A vertical tool of the default size (5 mm radius, 30 cm shaft), bounded at 5 N: above the
// demo's bowel, or at the bottom of dense_pile's cube.
constexpr double kToolMaxForce = 5.0;  // N
const char* kTool = R"(
  "tools": [{"radius": 0.005, "length": 0.3, "max_force": 5, "position": [0, 0, 0.14]}],)";
const char* kSweepTool = R"(
  "tools": [{"radius": 0.005, "length": 0.3, "max_force": 5, "position": [-0.045, 0, -0.045]}],)";

std::vector<HardCase> make_cases() {
    constexpr double kEnergy = 1e-3;  // J
    constexpr double kToolReach = 0.005 + kRadius;  // m
    constexpr double kSettled = 0.5 * kRadius, kLargeStep = kRadius, kCentresApart = 2.0 * kRadius;
    using S = ent_scene*;
    // name, what, dt, penetration bound, settle, energy allowance, make, drive
    return {
        {"dense_pile", "6 m bowel dropped into an open-top 12 cm cube, self-colliding", 1e-3, kSettled, 0.0, kEnergy,
         [] { return from_json(dropped_bowel("implicit_euler")); }, nullptr},
        {"dense_pile_closed", "6 m bowel (2.9 L) packed into a closed 12 cm cube (1.7 L)", 1e-3, kCentresApart, 1.0,
         kEnergy, [] { return packed_in_closed_cube(ENT_INTEGRATOR_IMPLICIT_EULER); }, nullptr},
        {"stiff_rk4", "hanging 6 m bowel, stretch stiffness 100x (1e4 N), rk4 at 1 ms", 1e-3, 0.0, 0.0, kEnergy,
         [] { return from_json(demo_bowel("rk4", 1e-3, 1e4, false)); }, nullptr},
        // Symplectic Euler's energy oscillates (boundedly) about the true one: 2.9 mJ measured.
        {"stiff_symplectic_euler", "the same, symplectic Euler at 1 ms", 1e-3, 0.0, 0.0, 0.01,
         [] { return from_json(demo_bowel("symplectic_euler", 1e-3, 1e4, false)); }, nullptr},
        // Contacts that appear within a 50 ms step are not in its linearisation, so a step
        // can gain energy; the guard retries one that gains more than 10 %, but accepts
        // smaller gains, and they add up while the bowel lands: 0.41 J above E0 = 0.59 J at
        // t = 1 s (measured), lost again by t = 2 s. Bounded, not zero: 0.6 J.
        {"large_steps_implicit_euler", "demo bowel in its cavity, self-colliding, steps and substeps of 50 ms", 0.05,
         kLargeStep, 0.0, 0.6, [] { return from_json(demo_bowel("implicit_euler", 0.05, 100, true)); }, nullptr},
        {"large_steps_symplectic_euler", "hanging 6 m bowel, steps of 50 ms (substeps: the stability limit)", 0.05,
         0.0, 0.0, kEnergy, [] { return from_json(demo_bowel("symplectic_euler", 0.05, 100, false)); }, nullptr},
        {"large_steps_rk4", "the same, rk4", 0.05, 0.0, 0.0, kEnergy,
         [] { return from_json(demo_bowel("rk4", 0.05, 100, false)); }, nullptr},
        {"overstretched_implicit_euler", "6 m bowel pinned at both ends 7.8 m apart (30 % over-stretched)", 1e-3,
         0.0, 0.0, kEnergy, []() -> S { return overstretched(ENT_INTEGRATOR_IMPLICIT_EULER); }, nullptr},
        {"overstretched_symplectic_euler", "the same, symplectic Euler", 1e-3, 0.0, 0.0, kEnergy,
         []() -> S { return overstretched(ENT_INTEGRATOR_SYMPLECTIC_EULER); }, nullptr},
        // Coincident spheres start 2R deep (48 J) with an arbitrary normal; 0.69 J measured.
        {"degenerate_implicit_euler", "coincident, collinear, folded-back control points, self-colliding on a floor",
         1e-3, kCentresApart, 0.5, 2.0, []() -> S { return degenerate(ENT_INTEGRATOR_IMPLICIT_EULER, true); },
         nullptr},
        {"degenerate_symplectic_euler", "the same points, first end held, no contacts, symplectic Euler", 1e-3,
         0.0, 0.0, kEnergy, []() -> S { return degenerate(ENT_INTEGRATOR_SYMPLECTIC_EULER, false); }, nullptr},
        {"degenerate_rk4", "the same, rk4", 1e-3, 0.0, 0.0, kEnergy,
         []() -> S { return degenerate(ENT_INTEGRATOR_RK4, false); }, nullptr},
        {"collapsed_implicit_euler", "every control point at one place (zero-length axis), first end held", 1e-3,
         0.0, 0.0, kEnergy, []() -> S { return collapsed(ENT_INTEGRATOR_IMPLICIT_EULER); }, nullptr},
        // The tools' forces on the bowel are bounded (5 N in all), so a fast tool passes
        // through the bowel and a teleported one lands on the axis: a sphere may get as deep
        // as the tool's radius + R (17.5 mm, its centre on the tool's axis); the bound holds
        // the cavity's and the folds' contacts to it too. Energy: the tools' work is in the
        // budget.
        {"fast_tool_sweep", "a tool sweeping at 10 m/s through the pile of dense_pile, back and forth", 1e-3,
         kToolReach, 0.0, kEnergy, [] { return from_json(dropped_bowel("implicit_euler", kSweepTool)); },
         [] {
             const double tip[3] = {-0.045, 0.0, -0.045};
             return make_sweep(10.0, -0.045, 0.045, tip);
         }},
        {"yank", "demo bowel grasped every 2 s and pulled up at 1 m/s for 0.5 s, far past max_force", 1e-3,
         kToolReach, 0.0, kEnergy, [] { return from_json(demo_bowel("implicit_euler", 1e-3, 100, true, kTool)); },
         [] { return make_yank(2.0, 1.0, 0.5, kToolMaxForce); }},
        {"teleport", "demo bowel, a tool put on a control point within one step every 0.5 s", 1e-3, kToolReach, 0.0,
         kEnergy, [] { return from_json(demo_bowel("implicit_euler", 1e-3, 100, true, kTool)); },
         [] { return make_teleport(0.5, kToolMaxForce); }},
        // bdf2 (issue 21): every case of implicit Euler's above, with its bounds. Before its
        // order reduction (lib/mechanics/bdf2.h) it failed three: dense_pile 6.251 mm
        // penetration at t = 0.115 s, large_steps unstable at t = 0.1 s (+8 J in a 50 ms
        // step, mostly self-contact), degenerate +2.61 J at t = 3 ms (docs/accuracy.md#bdf2).
        {"dense_pile_bdf2", "dense_pile with bdf2", 1e-3, kSettled, 0.0, kEnergy,
         [] { return from_json(dropped_bowel("bdf2")); }, nullptr},
        {"dense_pile_closed_bdf2", "dense_pile_closed with bdf2", 1e-3, kCentresApart, 1.0, kEnergy,
         [] { return packed_in_closed_cube(ENT_INTEGRATOR_BDF2); }, nullptr},
        {"large_steps_bdf2", "large_steps_implicit_euler with bdf2", 0.05, kLargeStep, 0.0, 0.6,
         [] { return from_json(demo_bowel("bdf2", 0.05, 100, true)); }, nullptr},
        {"degenerate_bdf2", "degenerate_implicit_euler with bdf2", 1e-3, kCentresApart, 0.5, 2.0,
         []() -> S { return degenerate(ENT_INTEGRATOR_BDF2, true); }, nullptr},
        {"overstretched_bdf2", "overstretched_implicit_euler with bdf2", 1e-3, 0.0, 0.0, kEnergy,
         []() -> S { return overstretched(ENT_INTEGRATOR_BDF2); }, nullptr},
        {"collapsed_bdf2", "collapsed_implicit_euler with bdf2", 1e-3, 0.0, 0.0, kEnergy,
         []() -> S { return collapsed(ENT_INTEGRATOR_BDF2); }, nullptr},
        {"yank_bdf2", "yank with bdf2", 1e-3, kToolReach, 0.0, kEnergy,
         [] { return from_json(demo_bowel("bdf2", 1e-3, 100, true, kTool)); },
         [] { return make_yank(2.0, 1.0, 0.5, kToolMaxForce); }},
        {"fast_tool_sweep_bdf2", "fast_tool_sweep with bdf2", 1e-3, kToolReach, 0.0, kEnergy,
         [] { return from_json(dropped_bowel("bdf2", kSweepTool)); },
         [] {
             const double tip[3] = {-0.045, 0.0, -0.045};
             return make_sweep(10.0, -0.045, 0.045, tip);
         }},
        {"teleport_bdf2", "teleport with bdf2", 1e-3, kToolReach, 0.0, kEnergy,
         [] { return from_json(demo_bowel("bdf2", 1e-3, 100, true, kTool)); },
         [] { return make_teleport(0.5, kToolMaxForce); }},
    };
}

}  // namespace

const std::vector<HardCase>& hard_cases() {
    static const std::vector<HardCase> cases = make_cases();
    return cases;
}

}  // namespace stability
