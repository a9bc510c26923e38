// Wall time of one ent_scene_step(scene, 1 ms) for the 6 m small bowel with every
// mechanical effect (stretch, bend, damping, gravity, mesentery), per integrator and per
// number of control points. Through the C API only.
//
// Every benchmark iteration is one step, timed on its own with steady_clock (manual
// time); the counters median_us and p99_us come from those per-step samples, which is
// what a 1 kHz haptic loop cares about (the mean hides the slow steps). substeps_per_step
// shows how often an explicit integrator had to subdivide the step to stay stable.
// Each run first takes 200 untimed steps: the bowel starts at rest, and the first steps
// (and the first allocation) are not representative.
//
// Run it through scripts/bench, which turns the JSON output into bench/results/step_time.md.
#include <enteron/enteron.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

constexpr double step_s = 1e-3;
constexpr int warm_up_steps = 200;
constexpr double min_time_s = 0.5;

struct Integrator {
    const char* name;
    int32_t id;
};
constexpr Integrator integrators[] = {
    {"rk4", ENT_INTEGRATOR_RK4},
    {"symplectic_euler", ENT_INTEGRATOR_SYMPLECTIC_EULER},
    {"implicit_euler", ENT_INTEGRATOR_IMPLICIT_EULER},
};
constexpr uint32_t control_point_counts[] = {60, 120, 240, 480, 960};

std::string last_error(const char* call, ent_status status) {
    return std::string(call) + ": " + ent_status_string(status) + ": " + ent_last_error();
}

// The scene of the demo: 6 m, R = 12.5 mm, 0.3 kg/m, helix, all mechanical effects.
ent_scene_desc bowel_desc(int32_t integrator, uint32_t control_points) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                   ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
    desc.length_m = 6.0;
    desc.radius_m = 0.0125;
    desc.linear_density_kg_per_m = 0.3;
    desc.control_points = control_points;
    desc.stretch_stiffness_N = 100.0;
    desc.bend_stiffness_N_m2 = 2.5e-3;
    desc.shape = ENT_SHAPE_HELIX;
    desc.shape_center_m[0] = 0.0;
    desc.shape_center_m[1] = 0.0;
    desc.shape_center_m[2] = -0.15;
    desc.shape_helix_radius_m = 0.1;
    desc.shape_helix_pitch_m = 0.03;
    desc.integrator = integrator;
    desc.timestep_s = step_s;
    desc.pinned_ends = ENT_PIN_NONE;
    return desc;
}

bool read_stats(const ent_scene* scene, ent_stats* stats) {
    *stats = ent_stats{};
    stats->struct_size = sizeof(ent_stats);
    return ent_scene_stats(scene, stats) == ENT_OK;
}

// Nearest-rank quantile of sorted samples, q in (0, 1].
double quantile(const std::vector<double>& sorted, double q) {
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
    return sorted[std::min(sorted.size(), std::max<std::size_t>(rank, 1)) - 1];
}

void step_benchmark(benchmark::State& state, int32_t integrator, uint32_t control_points) {
    const ent_scene_desc desc = bowel_desc(integrator, control_points);
    ent_scene* scene = nullptr;
    ent_status status = ent_scene_create(&desc, &scene);
    if (status != ENT_OK) {
        state.SkipWithError(last_error("ent_scene_create", status).c_str());
        return;
    }
    for (int i = 0; i < warm_up_steps; ++i) {
        status = ent_scene_step(scene, step_s);
        if (status != ENT_OK) {
            state.SkipWithError(last_error("ent_scene_step (warm-up)", status).c_str());
            ent_scene_destroy(scene);
            return;
        }
    }
    ent_stats before;
    if (!read_stats(scene, &before)) {
        state.SkipWithError("ent_scene_stats failed");
        ent_scene_destroy(scene);
        return;
    }

    std::vector<double> samples_us;
    samples_us.reserve(static_cast<std::size_t>(state.max_iterations));
    bool failed = false;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        status = ent_scene_step(scene, step_s);
        const auto stop = std::chrono::steady_clock::now();
        if (status != ENT_OK) {
            state.SkipWithError(last_error("ent_scene_step", status).c_str());
            failed = true;
            break;
        }
        const double seconds = std::chrono::duration<double>(stop - start).count();
        state.SetIterationTime(seconds);
        samples_us.push_back(seconds * 1e6);
    }

    ent_stats after;
    if (!failed && !samples_us.empty() && read_stats(scene, &after)) {
        std::sort(samples_us.begin(), samples_us.end());
        const double steps = static_cast<double>(samples_us.size());
        state.counters["median_us"] = quantile(samples_us, 0.5);
        state.counters["p99_us"] = quantile(samples_us, 0.99);
        state.counters["max_us"] = samples_us.back();
        state.counters["substeps_per_step"] =
            static_cast<double>(after.substeps - before.substeps) / steps;
        state.counters["rollbacks"] = static_cast<double>(after.rollbacks - before.rollbacks);
        state.counters["control_points"] = control_points;
    }
    ent_scene_destroy(scene);
}

}  // namespace

int main(int argc, char** argv) {
    if ((ent_version() >> 16) != ENT_VERSION_MAJOR) {
        std::fprintf(stderr, "enteron_step_bench: libenteron major version %u, built for %d\n",
                     static_cast<unsigned>(ent_version() >> 16), ENT_VERSION_MAJOR);
        return 1;
    }
    for (const Integrator& integrator : integrators) {
        for (const uint32_t n : control_point_counts) {
            const std::string name = std::string("step/") + integrator.name + "/" + std::to_string(n);
            benchmark::RegisterBenchmark(name.c_str(), step_benchmark, integrator.id, n)
                ->UseManualTime()
                ->MinTime(min_time_s)
                ->Unit(benchmark::kMicrosecond);
        }
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
