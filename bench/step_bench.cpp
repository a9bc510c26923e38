// SPDX-License-Identifier: Apache-2.0
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

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "bowel_scene.h"
#include "step_timing.h"

namespace {

using namespace enteron::bench;

constexpr double step_s = kStepS;
constexpr int warm_up_steps = 200;
constexpr double min_time_s = 0.5;
constexpr uint32_t control_point_counts[] = {60, 120, 240, 480, 960};

// The scene of the demo: 6 m, R = 12.5 mm, 0.3 kg/m, helix, all mechanical effects.
ent_scene_desc step_bowel_desc(int32_t integrator, uint32_t control_points) {
    return bowel_desc(integrator, control_points,
                      ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                          ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                          ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY),
                      -0.15, 0.03);
}

void step_benchmark(benchmark::State& state, int32_t integrator, uint32_t control_points) {
    const ent_scene_desc desc = step_bowel_desc(integrator, control_points);
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
        status = timed_iteration(state, samples_us, [&] { return ent_scene_step(scene, step_s); });
        if (status != ENT_OK) {
            state.SkipWithError(last_error("ent_scene_step", status).c_str());
            failed = true;
            break;
        }
    }

    ent_stats after;
    if (!failed && !samples_us.empty() && read_stats(scene, &after)) {
        const double steps = static_cast<double>(samples_us.size());
        const StepTimeSummary summary = summarize(samples_us);
        state.counters["median_us"] = summary.median_us;
        state.counters["p99_us"] = summary.p99_us;
        state.counters["max_us"] = summary.max_us;
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
    for (const Integrator& integrator : kIntegrators) {
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
