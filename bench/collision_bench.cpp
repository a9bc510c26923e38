// SPDX-License-Identifier: Apache-2.0
// Wall time of one ent_scene_step(scene, 1 ms) of the 6 m small bowel piled in the
// abdominal cavity with every effect on: stretch, bend, damping, gravity, mesentery,
// environment (the inside of a 30 cm box), self-collision (spheres of radius R every R/2
// along the axis) and a tool pressed into the pile and sweeping it, per integrator. Through the C API only. The scene is the demo's
// (examples/demo.c) with N control points: a helix dropped near the floor of the box,
// held by its mesentery, settled for settle_s with implicit Euler. Every timed scene
// starts at rest from that settled pile (its control points as the initial shape, so the
// mesentery's springs take their lengths there): the explicit integrators need hundreds
// of substeps per step once self-contact is on, and settling each of them would take
// many minutes.
//
// With MuJoCo (ENTERON_BENCH_MUJOCO, Debian's libmujoco-dev), the same run also times
// MuJoCo's rope of the same length, point count, radius, mass per length, bending
// stiffness, time step, gravity, friction and self-collision rule in the same box
// (bench/peers/mujoco_rope.h), from the same settled pile, without the tool. It reports
// whether the rope stayed finite.
//
// Every benchmark iteration is one step, timed on its own (manual time); the counters
// median_us and p99_us come from those samples. Each benchmark runs a fixed number of
// steps (one call). scripts/bench-collision turns the JSON output into
// bench/results/collision_step_time.md.
#include <enteron/enteron.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "bowel_scene.h"
#include "step_timing.h"

#ifdef ENTERON_HAVE_MUJOCO
#include "peers/mujoco_rope.h"
#endif

namespace {

using namespace enteron::bench;

constexpr double step_s = kStepS;
constexpr double settle_s = 2.0;
constexpr double box_half_extent_m = 0.15;

// Steps timed per integrator: a simulated second for implicit Euler, less for the explicit
// integrators, whose steps cost hundreds of substeps with self-contact.
int timed_steps(int32_t integrator) {
    return integrator == ENT_INTEGRATOR_IMPLICIT_EULER || integrator == ENT_INTEGRATOR_BDF2 ? 1000 : 100;
}

// N = 240 is the target; the smaller ones show how the gap to MuJoCo grows with N.
constexpr uint32_t control_point_counts[] = {60, 120, 240};

// The demo's bowel (examples/demo.c): every effect; the box comes with cavity_desc().
// Collision spheres every R / 2 (the default spacing 0).
ent_scene_desc collision_bowel_desc(int32_t integrator, uint32_t control_points) {
    return bowel_desc(integrator, control_points,
                      ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                          ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                          ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION),
                      -0.13, 0.025);
}

ent_obstacle_desc cavity_desc() {
    ent_obstacle_desc box;
    ent_obstacle_desc_default(&box);
    box.kind = ENT_OBSTACLE_BOX_INSIDE;
    for (int c = 0; c < 3; ++c) {
        box.center_m[c] = 0.0;
        box.half_extents_m[c] = box_half_extent_m;
    }
    return box;
}

// Our bowel in the cavity; settle_steps steps taken. Returns nullptr (and the message) on
// failure. `points`, if not empty, is the initial shape (N x 3, m).
ent_scene* bowel_in_cavity(int32_t integrator, uint32_t control_points, const std::vector<double>& points,
                           int settle_steps, std::string* error) {
    ent_scene_desc desc = collision_bowel_desc(integrator, control_points);
    if (!points.empty()) {
        desc.shape = ENT_SHAPE_POINTS;
        desc.shape_points_xyz_m = points.data();
    }
    ent_scene* scene = nullptr;
    ent_status status = ent_scene_create(&desc, &scene);
    if (status != ENT_OK) {
        *error = last_error("ent_scene_create", status);
        return nullptr;
    }
    const ent_obstacle_desc box = cavity_desc();
    status = ent_scene_add_obstacle(scene, &box, nullptr);
    if (status != ENT_OK) {
        *error = last_error("ent_scene_add_obstacle", status);
        ent_scene_destroy(scene);
        return nullptr;
    }
    for (int i = 0; i < settle_steps; ++i) {
        status = ent_scene_step(scene, step_s);
        if (status != ENT_OK) {
            *error = last_error("ent_scene_step (settling)", status);
            ent_scene_destroy(scene);
            return nullptr;
        }
    }
    return scene;
}

// The control points of the bowel settled with implicit Euler, once per N (shared by every
// benchmark of that N). Empty, with the message in *error, on failure.
const std::vector<double>& settled_pile(uint32_t control_points, std::string* error) {
    static std::vector<std::pair<uint32_t, std::vector<double>>> piles;
    for (const auto& [n, points] : piles)
        if (n == control_points) return points;
    std::vector<double> points;
    const int settle_steps = static_cast<int>(std::lround(settle_s / step_s));
    ent_scene* scene = bowel_in_cavity(ENT_INTEGRATOR_IMPLICIT_EULER, control_points, {}, settle_steps, error);
    if (scene != nullptr) {
        points.resize(3 * static_cast<std::size_t>(control_points));
        uint32_t count = 0;
        const ent_status status = ent_scene_control_points(scene, control_points, points.data(), &count);
        if (status != ENT_OK) {
            *error = last_error("ent_scene_control_points", status);
            points.clear();
        }
        ent_scene_destroy(scene);
    }
    if (points.empty()) {
        static const std::vector<double> none;
        return none;
    }
    piles.emplace_back(control_points, std::move(points));
    return piles.back().second;
}

void set_timing_counters(benchmark::State& state, std::vector<double>& samples_us) {
    const StepTimeSummary summary = summarize(samples_us);
    state.counters["median_us"] = summary.median_us;
    state.counters["p99_us"] = summary.p99_us;
    state.counters["max_us"] = summary.max_us;
}

// Wall time spent in each effect so far, ns (ENT_EFFECT_* order; 0 for effects off).
std::vector<uint64_t> effect_times_ns(const ent_scene* scene) {
    std::vector<uint64_t> times(ENT_EFFECT_COUNT, 0);
    for (int32_t effect = 0; effect < ENT_EFFECT_COUNT; ++effect) {
        ent_effect_stats stats{};
        stats.struct_size = sizeof stats;
        if (ent_scene_effect_stats(scene, effect, &stats) == ENT_OK) times[effect] = stats.total_time_ns;
    }
    return times;
}

bool axis_finite(const ent_scene* scene, uint32_t control_points) {
    std::vector<double> points(3 * static_cast<std::size_t>(control_points));
    uint32_t count = 0;
    if (ent_scene_control_points(scene, control_points, points.data(), &count) != ENT_OK) return false;
    return std::all_of(points.begin(), points.end(), [](double x) { return std::isfinite(x); });
}

// The tool in contact: a grasper (the default tool, 5 mm shaft) coming down vertically onto
// the highest control point of the pile and holding its tip tool_press_m into the bowel
// above that point as the point moves, while sliding tool_sweep_m back and forth along x
// at tool_sweep_hz (friction drags the surface), its pose set before every step from the
// last published state, as a haptic loop would.
constexpr double tool_press_m = 0.005;
constexpr double tool_sweep_m = 0.01;
constexpr double tool_sweep_hz = 1.0;
constexpr double kPi = 3.14159265358979323846;

std::size_t highest_point(const std::vector<double>& points) {
    std::size_t top = 0;
    for (std::size_t i = 0; 3 * i < points.size(); ++i)
        if (points[3 * i + 2] > points[3 * top + 2]) top = i;
    return top;
}

// The tip over control point `held` of `points` at time_s.
void tool_position_at(const std::vector<double>& points, std::size_t held, double reach_m, double time_s,
                      double position_m[3]) {
    position_m[0] = points[3 * held] + tool_sweep_m * std::sin(2.0 * kPi * tool_sweep_hz * time_s);
    position_m[1] = points[3 * held + 1];
    position_m[2] = points[3 * held + 2] + reach_m;
}

void collision_benchmark(benchmark::State& state, int32_t integrator, uint32_t control_points) {
    std::string error;
    const std::vector<double>& pile = settled_pile(control_points, &error);
    if (pile.empty()) {
        state.SkipWithError(error.c_str());
        return;
    }
    ent_scene* scene = bowel_in_cavity(integrator, control_points, pile, 0, &error);
    if (scene == nullptr) {
        state.SkipWithError(error.c_str());
        return;
    }
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    const std::size_t held = highest_point(pile);
    // Tip above the axis point by the two radii less the press depth.
    const double reach_m = collision_bowel_desc(integrator, control_points).radius_m + tool.radius_m - tool_press_m;
    tool_position_at(pile, held, reach_m, 0.0, tool.position_m);  // the shaft rises from the tip along +z
    std::vector<double> points = pile;
    int32_t tool_id = -1;
    ent_status added = ent_tool_add(scene, &tool, &tool_id);
    if (added != ENT_OK) {
        state.SkipWithError(last_error("ent_tool_add", added).c_str());
        ent_scene_destroy(scene);
        return;
    }
    ent_stats before;
    if (!read_stats(scene, &before)) {
        state.SkipWithError("ent_scene_stats failed");
        ent_scene_destroy(scene);
        return;
    }
    const std::vector<uint64_t> effects_before = effect_times_ns(scene);

    std::vector<double> samples_us;
    samples_us.reserve(static_cast<std::size_t>(state.max_iterations));
    bool failed = false;
    double max_penetration_m = 0.0;
    uint64_t contacts = 0;
    double tool_force_sum_N = 0.0, tool_force_max_N = 0.0;
    uint64_t tool_touching_steps = 0;
    double tool_time_s = 0.0;
    for (auto _ : state) {
        tool_time_s += step_s;
        uint32_t count = 0;
        ent_scene_control_points(scene, control_points, points.data(), &count);
        double position[3];
        const double upright[4] = {1.0, 0.0, 0.0, 0.0};
        tool_position_at(points, held, reach_m, tool_time_s, position);
        ent_status status = ent_tool_set_pose(scene, tool_id, position, upright);
        if (status == ENT_OK)
            status = timed_iteration(state, samples_us, [&] { return ent_scene_step(scene, step_s); });
        if (status != ENT_OK) {
            state.SkipWithError(last_error("ent_tool_set_pose / ent_scene_step", status).c_str());
            failed = true;
            break;
        }
        ent_stats now;
        if (read_stats(scene, &now)) {
            max_penetration_m = std::max(max_penetration_m, now.max_penetration_m);
            contacts += now.contacts;
        }
        double force[3], torque[3];
        if (ent_tool_wrench(scene, tool_id, force, torque) == ENT_OK) {
            const double magnitude = std::sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
            tool_force_sum_N += magnitude;
            tool_force_max_N = std::max(tool_force_max_N, magnitude);
            tool_touching_steps += magnitude > 0.0 ? 1 : 0;
        }
    }

    ent_stats after;
    if (!failed && !samples_us.empty() && read_stats(scene, &after)) {
        const double steps = static_cast<double>(samples_us.size());
        const ent_scene_desc desc = collision_bowel_desc(integrator, control_points);
        const double spacing = desc.collision_sphere_spacing_m > 0.0 ? desc.collision_sphere_spacing_m
                                                                     : 0.5 * desc.radius_m;
        set_timing_counters(state, samples_us);
        state.counters["substeps_per_step"] = static_cast<double>(after.substeps - before.substeps) / steps;
        state.counters["rollbacks"] = static_cast<double>(after.rollbacks - before.rollbacks);
        state.counters["contacts"] = static_cast<double>(contacts) / steps;  // mean per step
        state.counters["max_penetration_m"] = max_penetration_m;
        state.counters["radius_m"] = desc.radius_m;
        // The sphere count of docs/scene-json.md, round(L / spacing) + 1.
        state.counters["spheres"] = std::round(desc.length_m / spacing) + 1.0;
        state.counters["control_points"] = control_points;
        state.counters["finite"] = axis_finite(scene, control_points) ? 1.0 : 0.0;
        state.counters["simulated_s"] = steps * step_s;
        state.counters["tool_force_mean_N"] = tool_force_sum_N / steps;
        state.counters["tool_force_max_N"] = tool_force_max_N;
        state.counters["tool_max_force_N"] = tool.max_force_N;
        state.counters["tool_touching"] = static_cast<double>(tool_touching_steps) / steps;  // fraction of steps
        // Where the step's time goes: mean us per step in each effect (the rest is the
        // integrator's own work: assembly, factorisation, solve, guard, publication).
        const std::vector<uint64_t> effects_after = effect_times_ns(scene);
        for (int32_t effect = 0; effect < ENT_EFFECT_COUNT; ++effect) {
            const char* name = ent_effect_name(effect);
            if (name == nullptr || effects_after[effect] == effects_before[effect]) continue;
            state.counters[std::string("effect_us_") + name] =
                static_cast<double>(effects_after[effect] - effects_before[effect]) * 1e-3 / steps;
        }
    }
    ent_scene_destroy(scene);
}

#ifdef ENTERON_HAVE_MUJOCO
// Steps timed for MuJoCo's rope; its step costs far more than ours, so fewer by default.
// ENTERON_BENCH_MUJOCO_STEPS overrides (e.g. 1000 for a whole simulated second).
int mujoco_timed_steps() {
    const char* text = std::getenv("ENTERON_BENCH_MUJOCO_STEPS");
    const int steps = text ? std::atoi(text) : 200;
    return steps > 0 ? steps : 200;
}

void mujoco_benchmark(benchmark::State& state, uint32_t control_points) {
    // The starting pile: our bowel settled with implicit Euler.
    std::string error;
    const std::vector<double>& pile = settled_pile(control_points, &error);
    if (pile.empty()) {
        state.SkipWithError(error.c_str());
        return;
    }
    const ent_scene_desc scene_desc = collision_bowel_desc(ENT_INTEGRATOR_IMPLICIT_EULER, control_points);
    enteron::peers::MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene_desc);
    desc.box = true;
    for (int c = 0; c < 3; ++c) {
        desc.box_center_m[c] = 0.0;
        desc.box_half_extents_m[c] = box_half_extent_m;
    }
    // Room for a dense pile: every capsule touching a few others and the walls (the settled
    // pile makes under two contacts per capsule; a full buffer is counted as an overflow).
    // Larger buffers only cost MuJoCo memory and creation time, not step time.
    desc.max_contacts = static_cast<int>(4 * control_points + 64);
    desc.max_constraint_rows = 4 * desc.max_contacts;
    desc.initial_points_xyz_m = pile;
    auto rope = enteron::peers::MujocoRope::create(desc, &error);
    if (!rope) {
        state.SkipWithError(error.c_str());
        return;
    }

    std::vector<double> samples_us;
    samples_us.reserve(static_cast<std::size_t>(state.max_iterations));
    bool finite = true;
    double max_penetration_m = 0.0;
    uint64_t contacts = 0;
    for (auto _ : state) {
        if (!finite) {  // keep iterating cheaply: the count was fixed up front
            state.SetIterationTime(0.0);
            continue;
        }
        finite = timed_iteration(state, samples_us, [&] { return rope->step(); });
        max_penetration_m = std::max(max_penetration_m, rope->max_penetration_m());
        contacts += static_cast<uint64_t>(rope->contacts());
    }
    if (samples_us.empty()) return;
    const double steps = static_cast<double>(samples_us.size());
    set_timing_counters(state, samples_us);
    state.counters["finite"] = finite ? 1.0 : 0.0;
    state.counters["contacts"] = static_cast<double>(contacts) / steps;
    state.counters["max_penetration_m"] = max_penetration_m;
    state.counters["buffer_overflows"] = rope->buffer_overflows();
    state.counters["control_points"] = control_points;
    state.counters["simulated_s"] = steps * desc.timestep_s;
    state.SetLabel(enteron::peers::mujoco_version() + ", " +
                   enteron::peers::mujoco_integrator_name(desc.integrator) + " integrator");
}
#endif

}  // namespace

int main(int argc, char** argv) {
    if ((ent_version() >> 16) != ENT_VERSION_MAJOR) {
        std::fprintf(stderr, "enteron_collision_bench: libenteron major version %u, built for %d\n",
                     static_cast<unsigned>(ent_version() >> 16), ENT_VERSION_MAJOR);
        return 1;
    }
    for (const uint32_t n : control_point_counts) {
        for (const Integrator& integrator : kIntegrators) {
            const std::string name = std::string("collision/") + integrator.name + "/" + std::to_string(n);
            benchmark::RegisterBenchmark(name.c_str(), collision_benchmark, integrator.id, n)
                ->UseManualTime()
                ->Iterations(timed_steps(integrator.id))
                ->Unit(benchmark::kMicrosecond);
        }
#ifdef ENTERON_HAVE_MUJOCO
        const std::string name = "collision/mujoco_rope/" + std::to_string(n);
        benchmark::RegisterBenchmark(name.c_str(), mujoco_benchmark, n)
            ->UseManualTime()
            ->Iterations(mujoco_timed_steps())
            ->Unit(benchmark::kMicrosecond);
#endif
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
