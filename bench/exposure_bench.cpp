// SPDX-License-Identifier: Apache-2.0
// The cost of the exposure query (ent_scene_exposure, docs/scoring-and-state.md): the 6 m
// bowel (N = 240) settled for 1.5 s into a pile on the floor of a 30 cm box, a target on
// the floor under the pile (points, or a disk of triangles sampled at 4 x 4 points each),
// seen from 25 cm above. Each configuration is measured 500 times in turn with the others
// (rounds alternate, so a burst of load on the shared machine hits them alike): wall and
// thread-CPU time per query, median and p99. A plain program printing a Markdown table.
//   build/bench/enteron_exposure_bench [rounds]
#include <enteron/enteron.h>

#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bowel_scene.h"
#include "step_timing.h"

namespace {

using enteron::bench::last_error;

double thread_cpu_us() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e6 * double(t.tv_sec) + 1e-3 * double(t.tv_nsec);
}

struct Config {
    std::string name;
    std::vector<double> points;
    std::vector<uint32_t> triangles;
    uint32_t chords_per_segment;
    ent_exposure* exposure = nullptr;
    std::vector<double> wall_us, cpu_us;
    ent_exposure_result last{};
};

// A disk of `rings` x 16 triangles of radius rho around (0, 0, z), or its vertices as points.
void disk(double rho, double z, int rings, std::vector<double>* points, std::vector<uint32_t>* triangles) {
    points->insert(points->end(), {0.0, 0.0, z});
    const int around = 16;
    for (int r = 1; r <= rings; ++r)
        for (int k = 0; k < around; ++k) {
            const double a = 2.0 * M_PI * (k + 0.5 * (r % 2)) / around, radius = rho * r / rings;
            points->insert(points->end(), {radius * std::cos(a), radius * std::sin(a), z});
        }
    if (triangles == nullptr) return;
    auto at = [&](int r, int k) { return r == 0 ? 0u : uint32_t(1 + (r - 1) * around + (k % around)); };
    for (int r = 0; r < rings; ++r)
        for (int k = 0; k < around; ++k) {
            if (r == 0) {
                triangles->insert(triangles->end(), {0u, at(1, k), at(1, k + 1)});
                continue;
            }
            triangles->insert(triangles->end(), {at(r, k), at(r + 1, k), at(r + 1, k + 1)});
            triangles->insert(triangles->end(), {at(r, k), at(r + 1, k + 1), at(r, k + 1)});
        }
}

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::atoi(argv[1]) : 500;
    // The pile: the step benchmarks' 6 m bowel in a 30 cm box, every contact effect.
    ent_scene_desc desc = enteron::bench::bowel_desc(
        ENT_INTEGRATOR_IMPLICIT_EULER, 240,
        ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) | ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) |
            ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) | ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION),
        -0.1, 0.03);
    ent_scene* scene = nullptr;
    ent_status status = ent_scene_create(&desc, &scene);
    if (status != ENT_OK) {
        std::fprintf(stderr, "%s\n", last_error("ent_scene_create", status).c_str());
        return 1;
    }
    ent_obstacle_desc box;
    ent_obstacle_desc_default(&box);
    box.half_extents_m[0] = box.half_extents_m[1] = box.half_extents_m[2] = 0.15;
    box.center_m[2] = 0.025;  // floor at z = -0.125
    if ((status = ent_scene_add_obstacle(scene, &box, nullptr)) != ENT_OK) {
        std::fprintf(stderr, "%s\n", last_error("ent_scene_add_obstacle", status).c_str());
        return 1;
    }
    for (int i = 0; i < 1500; ++i)
        if ((status = ent_scene_step(scene, 1e-3)) != ENT_OK) {
            std::fprintf(stderr, "%s\n", last_error("ent_scene_step", status).c_str());
            return 1;
        }
    const double floor_z = -0.125, eye[3] = {0.0, 0.0, 0.125};

    std::vector<Config> configs;
    auto add = [&](int rings, bool patch, uint32_t chords) {
        Config c;
        disk(0.08, floor_z, rings, &c.points, patch ? &c.triangles : nullptr);
        c.name = patch ? "disk of " + std::to_string(c.triangles.size() / 3) + " triangles, 4 x 4 samples each"
                       : std::to_string(c.points.size() / 3) + " points";
        c.chords_per_segment = chords;
        configs.push_back(std::move(c));
    };
    add(6, false, 4);
    add(63, false, 4);
    add(6, true, 2);
    add(6, true, 4);
    add(6, true, 8);
    for (Config& c : configs) {
        ent_exposure_desc d;
        ent_exposure_desc_default(&d);
        d.points_xyz_m = c.points.data();
        d.point_count = uint32_t(c.points.size() / 3);
        d.triangles = c.triangles.empty() ? nullptr : c.triangles.data();
        d.triangle_count = uint32_t(c.triangles.size() / 3);
        d.axis_chords_per_segment = c.chords_per_segment;
        if ((status = ent_exposure_create(scene, &d, &c.exposure)) != ENT_OK) {
            std::fprintf(stderr, "%s\n", last_error("ent_exposure_create", status).c_str());
            return 1;
        }
    }
    for (int round = 0; round < rounds; ++round)
        for (Config& c : configs) {
            c.last = ent_exposure_result{};
            c.last.struct_size = sizeof c.last;
            const double cpu0 = thread_cpu_us();
            const auto wall0 = std::chrono::steady_clock::now();
            status = ent_scene_exposure(scene, c.exposure, eye, &c.last);
            const auto wall1 = std::chrono::steady_clock::now();
            const double cpu1 = thread_cpu_us();
            if (status != ENT_OK) {
                std::fprintf(stderr, "%s\n", last_error("ent_scene_exposure", status).c_str());
                return 1;
            }
            c.wall_us.push_back(std::chrono::duration<double, std::micro>(wall1 - wall0).count());
            c.cpu_us.push_back(cpu1 - cpu0);
        }
    std::printf("The 6 m bowel (N = 240) piled on the floor of a 30 cm box, the target a disk of radius 8 cm "
                "under it seen from 25 cm above; %d queries of each, alternated.\n\n", rounds);
    std::printf("| target | axis chords per segment | samples | visible | spans | wall median us | wall p99 us | "
                "CPU median us | CPU p99 us |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (Config& c : configs) {
        const auto wall = enteron::bench::summarize(c.wall_us);
        const auto cpu = enteron::bench::summarize(c.cpu_us);
        std::printf("| %s | %u | %u | %.3f | %u | %.0f | %.0f | %.0f | %.0f |\n", c.name.c_str(), c.chords_per_segment,
                    c.last.samples, c.last.visible_fraction, c.last.span_count, wall.median_us, wall.p99_us,
                    cpu.median_us, cpu.p99_us);
        ent_exposure_destroy(c.exposure);
    }
    ent_scene_destroy(scene);
    return 0;
}
