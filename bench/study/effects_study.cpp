// SPDX-License-Identifier: Apache-2.0
// Only the effects a scene names cost anything.
//
// 1. The cost of each effect on the 6 m pile (study_scenes.h, every effect but pinned),
//    from ent_scene_effect_stats over a window after the pile has settled: microseconds
//    per 1 ms step and share of the whole step.
// 2. Three variants of one 6 m bowel, stepped in interleaved rounds so that they share
//    the machine's load: gravity only (a minimal document, stiffnesses 0); the pile
//    document with every other effect key deleted (what is left: intestine with
//    stiffnesses 0, solver, gravity, collision parameters); the pile document with every
//    other effect present at zero strength (damping, mesentery and contact stiffness 0,
//    nothing pinned, one tool parked above the cavity), which moves exactly alike but
//    still runs them; a zero stiffness turns the bowel's elasticity off in all three (it
//    has no key of its own). Per round, each variant's
//    median step time is divided by the gravity-only one's; the study reports the median
//    ratio over rounds, and which effects each variant ran (enabled, calls).
#include "effects_study.h"

#include "study_scenes.h"

#include <algorithm>
#include <cmath>

namespace study {

namespace {

const char* kShape = "\"shape\": {\"kind\": \"helix\", \"center\": [0, 0, -0.13], \"helix_radius\": 0.1,"
                     " \"helix_pitch\": 0.025}";

std::string gravity_only_json() {
    return format("{\"intestine\": {\"length\": 6.0, \"control_points\": 240,"
                  " \"stretch_stiffness\": 0, \"bend_stiffness\": 0, %s},"
                  " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},"
                  " \"gravity\": [0, 0, -9.81]}",
                  kShape);
}

std::string others_absent_json() {
    return format("{\"intestine\": {\"length\": 6.0, \"radius\": 0.0125, \"control_points\": 240,"
                  " \"linear_density\": 0.3, \"stretch_stiffness\": 0, \"bend_stiffness\": 0, %s},"
                  " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},"
                  " \"gravity\": [0, 0, -9.81],"
                  " \"collision\": {\"sphere_spacing\": 0, \"stiffness\": 500}}",
                  kShape);
}

std::string others_zero_json() {
    return format("{\"intestine\": {\"length\": 6.0, \"radius\": 0.0125, \"control_points\": 240,"
                  " \"linear_density\": 0.3, \"stretch_stiffness\": 0, \"bend_stiffness\": 0, %s},"
                  " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},"
                  " \"gravity\": [0, 0, -9.81],"
                  " \"damping\": {\"drag\": 0, \"stretch\": 0, \"bend\": 0},"
                  " \"mesentery\": {\"root\": [[-0.075, 0, 0], [0.075, 0, 0]], \"stiffness\": 0,"
                  " \"attachments\": 60, \"rest_length\": 0},"
                  " \"pinned\": {\"ends\": \"none\"},"
                  " \"collision\": {\"sphere_spacing\": 0, \"stiffness\": 0, \"damping\": 0, \"friction\": 0},"
                  " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0],"
                  " \"half_extents\": [0.15, 0.15, 0.15]}],"
                  " \"self_collision\": {},"
                  " \"tools\": [{\"position\": [0, 0, 0.5]}]}",
                  kShape);
}

void effect_costs(const Options& options) {
    const double settle_s = options.fast ? 0.5 : 2.0;
    const double measure_s = options.fast ? 0.5 : 1.0;
    ScenePtr scene = make_scene(pile_json(PileSettings{}));
    for (long k = 0; k < std::lround(settle_s / 1e-3); ++k) check(ent_scene_step(scene.get(), 1e-3), "ent_scene_step");
    ent_effect_stats before[ENT_EFFECT_COUNT];
    for (int32_t e = 0; e < ENT_EFFECT_COUNT; ++e) before[e] = effect_stats(scene.get(), e);
    const ent_stats start = scene_stats(scene.get());
    std::vector<double> step_us;
    const long steps = std::lround(measure_s / 1e-3);
    for (long k = 0; k < steps; ++k) {
        const double t0 = now_s();
        check(ent_scene_step(scene.get(), 1e-3), "ent_scene_step");
        step_us.push_back((now_s() - t0) * 1e6);
    }
    const ent_stats end = scene_stats(scene.get());
    double total_us = 0.0;
    for (double us : step_us) total_us += us;
    const double mean_step_us = total_us / static_cast<double>(steps);
    Csv csv(options.out_dir + "/effects_cost.csv",
            {"effect", "enabled", "calls_per_step", "us_per_step", "share_of_step", "step_median_us", "step_mean_us",
             "substeps_per_step"});
    for (int32_t e = 0; e < ENT_EFFECT_COUNT; ++e) {
        const ent_effect_stats after = effect_stats(scene.get(), e);
        const double calls = static_cast<double>(after.calls - before[e].calls) / static_cast<double>(steps);
        const double us = 1e-3 * static_cast<double>(after.total_time_ns - before[e].total_time_ns) /
                          static_cast<double>(steps);
        csv.row({ent_effect_name(e), num(after.enabled), num(calls), num(us), num(us / mean_step_us),
                 num(median(step_us)), num(mean_step_us),
                 num(static_cast<double>(end.substeps - start.substeps) / static_cast<double>(steps))});
        progress("effects %-15s enabled %d: %8.2f us per step (%.0f %%)", ent_effect_name(e), after.enabled, us,
                 100 * us / mean_step_us);
    }
}

struct Variant {
    const char* name;
    std::string json;
    ScenePtr scene;
    std::vector<double> all_us;
};

void absent_effects(const Options& options) {
    const int rounds = options.fast ? 3 : 9;
    const int steps_per_round = options.fast ? 100 : 300;
    Variant variants[3] = {{"gravity_only", gravity_only_json(), nullptr, {}},
                           {"others_absent", others_absent_json(), nullptr, {}},
                           {"others_zero_strength", others_zero_json(), nullptr, {}}};
    for (Variant& v : variants) v.scene = make_scene(v.json);
    std::vector<double> ratios[3];
    for (int round = 0; round < rounds; ++round) {
        double medians[3];
        for (int i = 0; i < 3; ++i) {
            std::vector<double> us;
            for (int k = 0; k < steps_per_round; ++k) {
                const double t0 = now_s();
                check(ent_scene_step(variants[i].scene.get(), 1e-3), "ent_scene_step");
                us.push_back((now_s() - t0) * 1e6);
            }
            medians[i] = median(us);
            variants[i].all_us.insert(variants[i].all_us.end(), us.begin(), us.end());
        }
        for (int i = 0; i < 3; ++i) ratios[i].push_back(medians[i] / medians[0]);
    }
    Csv csv(options.out_dir + "/effects_absent.csv",
            {"variant", "step_median_us", "ratio_to_gravity_only", "ratio_min", "ratio_max", "rounds",
             "effects_enabled", "effects_called", "axis_difference_m"});
    const std::vector<double> reference_axis = sample_axis(variants[0].scene.get(), 201);
    for (int i = 0; i < 3; ++i) {
        std::string enabled, called;
        for (int32_t e = 0; e < ENT_EFFECT_COUNT; ++e) {
            const ent_effect_stats s = effect_stats(variants[i].scene.get(), e);
            if (s.enabled) enabled += std::string(enabled.empty() ? "" : " ") + ent_effect_name(e);
            if (s.calls) called += std::string(called.empty() ? "" : " ") + ent_effect_name(e);
        }
        const double difference = rms_distance(sample_axis(variants[i].scene.get(), 201), reference_axis);
        csv.row({variants[i].name, num(median(variants[i].all_us)), num(median(ratios[i])),
                 num(*std::min_element(ratios[i].begin(), ratios[i].end())),
                 num(*std::max_element(ratios[i].begin(), ratios[i].end())), num(rounds), enabled, called,
                 num(difference)});
        progress("effects %-20s %7.2f us/step, ratio %.3f (%s)", variants[i].name, median(variants[i].all_us),
                 median(ratios[i]), enabled.c_str());
    }
}

}  // namespace

void run_effects_study(const Options& options) {
    effect_costs(options);
    absent_effects(options);
}

}  // namespace study
