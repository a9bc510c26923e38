// SPDX-License-Identifier: Apache-2.0
// Moving anatomy (docs/anatomy.md), through the C API only, printed as Markdown tables:
//  1. mesh preparation: the wall time of ent_scene_add_obstacle for a closed ellipsoid mesh
//     (an organ 20 x 14 x 10 cm) of 10k, 100k and 1M triangles, at the default voxel size
//     (R / 4) and at R / 2;
//  2. the step: one ent_scene_step(1 ms) of the 6 m bowel with N = 240 control points
//     (every effect, implicit Euler) piled in the 30 cm box of bench/collision_bench.cpp,
//     next to the same pile settled around three organ meshes (20k triangles each), and
//     with one of them (the liver) moved at every step like breathing (1 cm at 0.5 Hz).
//     Each scene settles 2 s first; then 1000 steps are timed one by one: median and p99.
// Reported, not asserted (timing tests do not pass or fail here). Run:
//   build/bench/enteron_anatomy_bench [--quick]
#include <enteron/enteron.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "bowel_scene.h"
#include "step_timing.h"

namespace {

using namespace enteron::bench;

struct Mesh {
    std::vector<double> vertices;
    std::vector<uint32_t> triangles;
};

// A closed ellipsoid with semi-axes a about c, normals out: `rings` x `segments` quads,
// fans at the poles; 2 segments (rings - 1) triangles.
Mesh ellipsoid(const double c[3], const double a[3], uint32_t rings, uint32_t segments) {
    Mesh m;
    m.vertices.insert(m.vertices.end(), {c[0], c[1], c[2] - a[2]});
    for (uint32_t i = 1; i < rings; ++i) {
        const double theta = M_PI * i / rings;  // from the south pole
        for (uint32_t j = 0; j < segments; ++j) {
            const double phi = 2.0 * M_PI * j / segments;
            m.vertices.insert(m.vertices.end(), {c[0] + a[0] * std::sin(theta) * std::cos(phi),
                                                 c[1] + a[1] * std::sin(theta) * std::sin(phi),
                                                 c[2] - a[2] * std::cos(theta)});
        }
    }
    m.vertices.insert(m.vertices.end(), {c[0], c[1], c[2] + a[2]});
    const uint32_t north = static_cast<uint32_t>(m.vertices.size() / 3 - 1);
    auto at = [&](uint32_t ring, uint32_t j) { return 1 + (ring - 1) * segments + j % segments; };
    for (uint32_t j = 0; j < segments; ++j) m.triangles.insert(m.triangles.end(), {0, at(1, j + 1), at(1, j)});
    for (uint32_t i = 1; i + 1 < rings; ++i)
        for (uint32_t j = 0; j < segments; ++j)
            m.triangles.insert(m.triangles.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j),
                                                   at(i + 1, j + 1), at(i + 1, j)});
    for (uint32_t j = 0; j < segments; ++j)
        m.triangles.insert(m.triangles.end(), {north, at(rings - 1, j), at(rings - 1, j + 1)});
    return m;
}

ent_obstacle_desc mesh_desc(const Mesh& m, double voxel_size_m) {
    ent_obstacle_desc d;
    ent_obstacle_desc_default(&d);
    d.kind = ENT_OBSTACLE_MESH;
    d.mesh_vertices_xyz_m = m.vertices.data();
    d.mesh_vertex_count = static_cast<uint32_t>(m.vertices.size() / 3);
    d.mesh_triangles = m.triangles.data();
    d.mesh_triangle_count = static_cast<uint32_t>(m.triangles.size() / 3);
    d.mesh_voxel_size_m = voxel_size_m;
    return d;
}

bool ok(ent_status status, const char* call) {
    if (status == ENT_OK) return true;
    std::fprintf(stderr, "anatomy_bench: %s\n", last_error(call, status).c_str());
    return false;
}

ent_scene_desc pile_desc() {
    return bowel_desc(ENT_INTEGRATOR_IMPLICIT_EULER, 240,
                      ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                          ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                          ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION),
                      -0.13, 0.025);
}

// CPU time of the whole process (Embree's threads included), ms: on a loaded machine the
// wall time counts the other processes' turns too.
double process_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

void preparation_table(bool quick) {
    std::printf("| triangles | voxel size | ent_scene_add_obstacle wall ms | CPU ms (all threads) |\n|---:|---|---:|---:|\n");
    const double c[3] = {0.0, 0.0, 0.0}, a[3] = {0.1, 0.07, 0.05};
    struct Size {
        uint32_t rings, segments;
    };
    const Size sizes[] = {{51, 100}, {201, 250}, {501, 1000}};  // 10k, 100k, 1M triangles
    const double radius = 0.0125;
    for (const Size& size : sizes) {
        if (quick && size.rings > 201) break;
        const Mesh m = ellipsoid(c, a, size.rings, size.segments);
        for (double voxel : {0.0, radius / 2}) {
            ent_scene_desc desc = pile_desc();
            desc.shape_center_m[2] = 0.5;  // far above the organ
            ent_scene* scene = nullptr;
            if (!ok(ent_scene_create(&desc, &scene), "ent_scene_create")) return;
            const ent_obstacle_desc d = mesh_desc(m, voxel);
            const double cpu_start = process_cpu_ms();
            const auto start = std::chrono::steady_clock::now();
            const bool added = ok(ent_scene_add_obstacle(scene, &d, nullptr), "ent_scene_add_obstacle");
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            const double cpu_ms = process_cpu_ms() - cpu_start;
            if (added)
                std::printf("| %zu | %s | %.0f | %.0f |\n", m.triangles.size() / 3, voxel == 0.0 ? "R/4 (default)" : "R/2",
                            ms, cpu_ms);
            ent_scene_destroy(scene);
        }
    }
}

enum class Organs { none, still, breathing };

void step_row(Organs organs, int steps) {
    ent_scene_desc desc = pile_desc();
    ent_scene* scene = nullptr;
    if (!ok(ent_scene_create(&desc, &scene), "ent_scene_create")) return;
    ent_obstacle_desc box;
    ent_obstacle_desc_default(&box);
    box.kind = ENT_OBSTACLE_BOX_INSIDE;
    for (double& h : box.half_extents_m) h = 0.15;
    bool made = ok(ent_scene_add_obstacle(scene, &box, nullptr), "ent_scene_add_obstacle");
    // Inside the helix's coil and in two corners of the box, clear of the helix at the start.
    const double centers[3][3] = {{0.0, 0.0, -0.11}, {0.11, 0.11, -0.11}, {-0.11, 0.11, -0.11}};
    const double axes[3][3] = {{0.06, 0.06, 0.035}, {0.035, 0.035, 0.035}, {0.035, 0.035, 0.035}};
    int32_t liver = -1;
    std::vector<Mesh> meshes;
    if (organs != Organs::none)
        for (int k = 0; k < 3 && made; ++k) {
            meshes.push_back(ellipsoid(centers[k], axes[k], 101, 100));  // 20k triangles
            const ent_obstacle_desc d = mesh_desc(meshes.back(), 0.0);
            made = ok(ent_scene_add_obstacle(scene, &d, k == 1 ? &liver : nullptr), "ent_scene_add_obstacle (mesh)");
        }
    for (int i = 0; i < 2000 && made; ++i) made = ok(ent_scene_step(scene, kStepS), "ent_scene_step (settling)");
    std::vector<double> samples;
    samples.reserve(static_cast<std::size_t>(steps));
    const double identity[4] = {1.0, 0.0, 0.0, 0.0};
    ent_stats stats;
    uint32_t most_contacts = 0;
    for (int i = 0; i < steps && made; ++i) {
        const auto start = std::chrono::steady_clock::now();
        if (organs == Organs::breathing) {
            const double lift[3] = {0.0, 0.0, 0.01 * std::sin(2.0 * M_PI * 0.5 * (i + 1) * kStepS)};
            made = ok(ent_obstacle_set_pose(scene, liver, lift, identity), "ent_obstacle_set_pose");
        }
        made = made && ok(ent_scene_step(scene, kStepS), "ent_scene_step");
        samples.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
        if (made && read_stats(scene, &stats)) most_contacts = std::max(most_contacts, stats.contacts);
    }
    if (made) {
        const StepTimeSummary s = summarize(samples);
        const char* name = organs == Organs::none        ? "box only"
                           : organs == Organs::still     ? "box + 3 organ meshes"
                                                         : "box + 3 organ meshes, liver breathing";
        std::printf("| %s | %.0f | %.0f | %u |\n", name, s.median_us, s.p99_us, most_contacts);
    }
    ent_scene_destroy(scene);
}

}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    std::printf("Mesh preparation (closed ellipsoid 20 x 14 x 10 cm, R = 12.5 mm):\n\n");
    preparation_table(quick);
    const int steps = quick ? 200 : 1000;
    std::printf("\nStep of the 6 m bowel, N = 240, implicit Euler, 1 ms (%d steps after 2 s of settling):\n\n", steps);
    std::printf("| scene | median us | p99 us | most contacts |\n|---|---:|---:|---:|\n");
    // Alternated, so that a noisy minute spreads over all three.
    for (int round = 0; round < (quick ? 1 : 2); ++round)
        for (Organs organs : {Organs::none, Organs::still, Organs::breathing}) step_row(organs, steps);
    return 0;
}
