// SPDX-License-Identifier: Apache-2.0
// "After the first updates it allocates only when the mesh grows beyond any size it had
// before" (ent_skin_update in enteron.h): the demo's 6 m bowel dropped into the abdominal
// cavity (self-collision, mesentery, box), moving for 2 simulated seconds, skinned every
// 10 ms by each method (and the convolution's level of detail, whose ring count follows the
// bends), with every global allocation function of the process counting (counting_new.cpp,
// alloc_counter.c). After 10 warm-up updates, each counted ent_skin_update must allocate
// nothing unless its mesh has more vertices or triangles than every earlier one of that
// skin. ent_skin_mesh, which the render thread calls after each update, must never
// allocate. Links only the shared library, like a simulator would.
#include <enteron/enteron.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "alloc_counter.h"
#include "first_callers.h"

namespace {

constexpr char kScene[] =
    "{\"intestine\": {\"length\": 6.0, \"radius\": 0.0125, \"control_points\": 240, \"linear_density\": 0.3,"
    " \"stretch_stiffness\": 100, \"bend_stiffness\": 2.5e-3,"
    " \"shape\": {\"kind\": \"helix\", \"center\": [0, 0, -0.13], \"helix_radius\": 0.1, \"helix_pitch\": 0.025}},"
    " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},"
    " \"gravity\": [0, 0, -9.81], \"damping\": {\"drag\": 0.05, \"stretch\": 0.05, \"bend\": 0},"
    " \"mesentery\": {\"root\": [[-0.075, 0, 0], [0.075, 0, 0]], \"stiffness\": 5, \"attachments\": 60,"
    " \"rest_length\": 0},"
    " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0], \"half_extents\": [0.15, 0.15, 0.15]}],"
    " \"self_collision\": {}}";

struct Case {
    const char* name;
    int32_t method;
    double ring_spacing_radii, ring_chord_error_radii;
};
constexpr Case kCases[] = {
    {"tube", ENT_SKIN_TUBE, 0.5, 0.0},
    {"point_skeleton", ENT_SKIN_POINT_SKELETON, 0.5, 0.0},
    {"convolution", ENT_SKIN_CONVOLUTION, 0.5, 0.0},
    {"convolution lod", ENT_SKIN_CONVOLUTION, 1.0, 0.005},
};
constexpr int kCases_ = sizeof kCases / sizeof kCases[0];

struct Tracked {
    ent_skin* skin = nullptr;
    uint32_t most_vertices = 0, most_triangles = 0;
    int grown = 0, allocating = 0, counted = 0;
};

int failures = 0;

bool check(ent_status status, const char* call, const char* name) {
    if (status == ENT_OK) return true;
    alloc_counter_stop();
    std::printf("  %s: %s failed: %s: %s\n", name, call, ent_status_string(status), ent_last_error());
    ++failures;
    return false;
}

}  // namespace

int main() {
    std::printf("skin updates allocate only when the mesh grows (the demo's bowel, falling and settling):\n");
    // The counter must see allocations at all, or a passing run would prove nothing.
    alloc_counter_start();
    std::vector<char>* probe = new std::vector<char>(64);
    const unsigned long probes = alloc_counter_stop();
    delete probe;
    if (probes != 2) {
        std::printf("the allocation counter saw %lu of 2 probe allocations\n", probes);
        return 1;
    }

    ent_scene* scene = nullptr;
    if (!check(ent_scene_create_json(kScene, std::strlen(kScene), &scene), "ent_scene_create_json", "scene"))
        return 1;
    Tracked tracked[kCases_];
    for (int c = 0; c < kCases_; ++c) {
        ent_skin_desc desc;
        ent_skin_desc_default(&desc);
        desc.method = kCases[c].method;
        desc.ring_spacing_radii = kCases[c].ring_spacing_radii;
        desc.ring_chord_error_radii = kCases[c].ring_chord_error_radii;
        if (!check(ent_skin_create(scene, &desc, &tracked[c].skin), "ent_skin_create", kCases[c].name)) return 1;
    }
    ent_mesh_view view;
    std::memset(&view, 0, sizeof view);
    view.struct_size = sizeof view;
    bool ok = true;
    constexpr int kWarmUp = 10, kFrames = 200;
    for (int frame = 0; frame < kFrames && ok; ++frame) {
        for (int step = 0; step < 10 && ok; ++step) ok = check(ent_scene_step(scene, 1e-3), "ent_scene_step", "scene");
        for (int c = 0; c < kCases_ && ok; ++c) {
            Tracked& t = tracked[c];
            const bool counting = frame >= kWarmUp;
            if (counting) alloc_counter_start();
            ok = check(ent_skin_update(t.skin), "ent_skin_update", kCases[c].name);
            const unsigned long in_update = counting ? alloc_counter_stop() : 0;
            if (counting) alloc_counter_start();
            ok = ok && check(ent_skin_mesh(t.skin, &view), "ent_skin_mesh", kCases[c].name);
            const unsigned long in_mesh = counting ? alloc_counter_stop() : 0;
            if (!ok) break;
            const bool grew = view.vertex_count > t.most_vertices || view.triangle_count > t.most_triangles;
            t.most_vertices = view.vertex_count > t.most_vertices ? view.vertex_count : t.most_vertices;
            t.most_triangles = view.triangle_count > t.most_triangles ? view.triangle_count : t.most_triangles;
            if (!counting) continue;
            ++t.counted;
            t.grown += grew ? 1 : 0;
            t.allocating += in_update > 0 ? 1 : 0;
            if ((in_update > 0 && !grew) || in_mesh > 0) {
                ++failures;
                std::printf("  %-16s frame %3d: FAILED: %lu allocation(s) in ent_skin_update, %lu in ent_skin_mesh, "
                            "mesh %u vertices %u triangles, not beyond its largest; first callers:\n",
                            kCases[c].name, frame, in_update, in_mesh, view.vertex_count, view.triangle_count);
                print_first_callers(in_update + in_mesh);
            }
        }
    }
    for (int c = 0; c < kCases_; ++c) {
        const Tracked& t = tracked[c];
        std::printf("  %-16s %d updates counted: the mesh grew beyond its largest in %d, an update allocated in %d "
                    "(largest: %u vertices, %u triangles)\n",
                    kCases[c].name, t.counted, t.grown, t.allocating, t.most_vertices, t.most_triangles);
        if (ok && t.counted != kFrames - kWarmUp) ++failures;
        ent_skin_destroy(t.skin);
    }
    ent_scene_destroy(scene);
    if (failures != 0) {
        std::printf("%d failure(s)\n", failures);
        return 1;
    }
    std::printf("no allocation without growth\n");
    return 0;
}
