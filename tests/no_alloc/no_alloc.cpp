// SPDX-License-Identifier: Apache-2.0
// "Allocates nothing after the first step": the default scene (ent_scene_desc_default plus
// mesentery, damping and self-collision, in a box, with a tool) under each integrator (6 m
// for implicit Euler, 1 m for the explicit ones, which need many substeps with contacts), with every global allocation function of the
// process replaced by a counting one (operator new and delete here, malloc and friends in
// alloc_counter.c). After the first step the counter is reset; 200 steps and the queries a
// render or haptics thread makes every frame (axis, control points, stats, effect stats) and the
// tool calls of a haptic loop (pose, wrench, grasp, release, stiffness, stats, count) must then allocate nothing. Links only the shared library, like a simulator would.
// The same for moving anatomy: a mesh organ posed at every step, a pin and the mesentery on
// it, run-time velocity, friction, gravity and unpinning, the obstacle queries.
#include <enteron/enteron.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "alloc_counter.h"
#include "first_callers.h"

// ---- the test --------------------------------------------------------------------------------

namespace {

int failures = 0;
void* volatile keep = nullptr;

void report(const char* what, const char* integrator, unsigned long allocations) {
    if (allocations == 0) {
        std::printf("  %-16s %-28s no allocation\n", integrator, what);
        return;
    }
    ++failures;
    std::printf("  %-16s %-28s FAILED: %lu allocation(s); first callers:\n", integrator, what, allocations);
    print_first_callers(allocations);
}

bool check(ent_status status, const char* call) {
    if (status == ENT_OK) return true;
    alloc_counter_stop();
    std::printf("  %s failed: %s: %s\n", call, ent_status_string(status), ent_last_error());
    ++failures;
    return false;
}

void run(int32_t integrator, const char* name, double length_m, uint32_t control_points,
         int32_t clamped_ends = ENT_PIN_NONE) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.length_m = length_m;
    desc.control_points = control_points;
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) |
                    ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    desc.integrator = integrator;
    if (clamped_ends != ENT_PIN_NONE) {
        desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
        desc.clamped_ends = clamped_ends;
    }
    ent_scene* scene = nullptr;
    if (!check(ent_scene_create(&desc, &scene), "ent_scene_create")) return;
    ent_obstacle_desc box;
    ent_obstacle_desc_default(&box);
    box.kind = ENT_OBSTACLE_BOX_INSIDE;
    // Around the whole helix (radius 0.1 m, rising from the origin), as a cavity would be.
    box.center_m[2] = 0.2;
    box.half_extents_m[0] = box.half_extents_m[1] = box.half_extents_m[2] = 0.25;
    // A tool whose tip starts 3 cm above the middle of the axis and goes down through it.
    double middle[3 * 3];
    if (!check(ent_scene_add_obstacle(scene, &box, nullptr), "ent_scene_add_obstacle") ||
        !check(ent_scene_axis(scene, 3, middle), "ent_scene_axis")) {
        ent_scene_destroy(scene);
        return;
    }
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    for (int c = 0; c < 3; ++c) tool.position_m[c] = middle[3 + c];
    tool.position_m[2] += 0.03;
    if (!check(ent_tool_add(scene, &tool, nullptr), "ent_tool_add")) {
        ent_scene_destroy(scene);
        return;
    }
    const double upright[4] = {1.0, 0.0, 0.0, 0.0};
    double tip[3] = {tool.position_m[0], tool.position_m[1], tool.position_m[2]};
    double force[3], torque[3];
    int32_t grasping = 0;
    // Everything the caller needs is allocated before counting starts.
    constexpr uint32_t kAxisSamples = 200;
    std::vector<double> axis(3 * kAxisSamples), points(3 * std::size_t{desc.control_points});
    ent_stats stats;
    std::memset(&stats, 0, sizeof stats);
    stats.struct_size = sizeof stats;
    ent_effect_stats effect;
    std::memset(&effect, 0, sizeof effect);
    effect.struct_size = sizeof effect;
    uint32_t count = 0;
    double stiffness[9];
    ent_tool_stats tool_stats;
    std::memset(&tool_stats, 0, sizeof tool_stats);
    tool_stats.struct_size = sizeof tool_stats;
    int32_t tools = 0;

    if (check(ent_scene_step(scene, 1e-3), "first ent_scene_step")) {
        alloc_counter_start();
        bool ok = true;
        for (int i = 0; i < 200 && ok; ++i) {
            tip[2] -= 0.0003;  // 6 cm down in 200 steps, through the bowel
            ok = check(ent_tool_set_pose(scene, 0, tip, upright), "ent_tool_set_pose") &&
                 check(ent_scene_step(scene, 1e-3), "ent_scene_step") &&
                 check(ent_tool_wrench(scene, 0, force, torque), "ent_tool_wrench") &&
                 check(ent_tool_state(scene, 0, &grasping), "ent_tool_state") &&
                 check(ent_tool_stiffness(scene, 0, stiffness), "ent_tool_stiffness") &&
                 check(ent_tool_read_stats(scene, 0, &tool_stats), "ent_tool_read_stats") &&
                 check(ent_scene_tool_count(scene, &tools), "ent_scene_tool_count");
            if (ok && i == 100) ok = check(ent_tool_grasp(scene, 0), "ent_tool_grasp");
            if (ok && i == 150) ok = check(ent_tool_release(scene, 0), "ent_tool_release");
        }
        const unsigned long in_steps = alloc_counter_stop();
        if (ok) report("200 steps with a tool", name, in_steps);

        alloc_counter_start();
        ok = check(ent_scene_axis(scene, kAxisSamples, axis.data()), "ent_scene_axis") &&
             check(ent_scene_axis(scene, 2, axis.data()), "ent_scene_axis");
        const unsigned long in_axis = alloc_counter_stop();
        if (ok) report("ent_scene_axis", name, in_axis);

        alloc_counter_start();
        ok = check(ent_scene_control_points(scene, desc.control_points, points.data(), &count),
                   "ent_scene_control_points") &&
             check(ent_scene_stats(scene, &stats), "ent_scene_stats");
        for (int32_t e = 0; e < ENT_EFFECT_COUNT && ok; ++e)
            ok = check(ent_scene_effect_stats(scene, e, &effect), "ent_scene_effect_stats");
        const unsigned long in_queries = alloc_counter_stop();
        if (ok) report("points, stats, effect stats", name, in_queries);

        // Interleaved, as a simulator's threads would call them.
        alloc_counter_start();
        for (int i = 0; i < 20 && ok; ++i)
            ok = check(ent_scene_step(scene, 1e-3), "ent_scene_step") &&
                 check(ent_scene_axis(scene, kAxisSamples, axis.data()), "ent_scene_axis") &&
                 check(ent_scene_stats(scene, &stats), "ent_scene_stats");
        const unsigned long interleaved = alloc_counter_stop();
        if (ok) report("step + axis + stats x 20", name, interleaved);
        if (ok && stats.steps != 221) {
            std::printf("  %s: expected 221 steps, stats say %llu\n", name, (unsigned long long)stats.steps);
            ++failures;
        }
    }
    ent_scene_destroy(scene);
}

// Moving anatomy (issue 20): a 1 m bowel in a box with an organ mesh (a closed box of 12
// triangles) that the caller lifts into it at every step, a pin and the mesentery's root on
// that organ, its velocity and friction given and gravity tilted between steps, and the
// obstacle queries a renderer makes, and the exposure query of the organ's surface.
void run_moving_anatomy() {
    const char* name = "implicit_euler";
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.length_m = 1.0;
    desc.control_points = 40;
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_DAMPING);
    ent_scene* scene = nullptr;
    if (!check(ent_scene_create(&desc, &scene), "ent_scene_create")) return;
    ent_obstacle_desc box;
    ent_obstacle_desc_default(&box);
    box.center_m[2] = 0.2;
    box.half_extents_m[0] = box.half_extents_m[1] = box.half_extents_m[2] = 0.25;
    // A 6 cm cube under the helix's first turn, normals out.
    double vertices[8 * 3];
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k) vertices[3 * i + k] = ((i >> k) & 1 ? 0.03 : -0.03) + (k == 2 ? -0.03 : 0.0);
    const uint32_t triangles[12 * 3] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                        2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    ent_obstacle_desc organ;
    ent_obstacle_desc_default(&organ);
    organ.kind = ENT_OBSTACLE_MESH;
    organ.mesh_vertices_xyz_m = vertices;
    organ.mesh_vertex_count = 8;
    organ.mesh_triangles = triangles;
    organ.mesh_triangle_count = 12;
    organ.position_m[0] = 0.1;
    int32_t organ_id = -1;
    bool made = check(ent_scene_add_obstacle(scene, &box, nullptr), "ent_scene_add_obstacle") &&
                check(ent_scene_add_obstacle(scene, &organ, &organ_id), "ent_scene_add_obstacle (mesh)") &&
                check(ent_scene_pin_point(scene, desc.control_points - 1, organ_id), "ent_scene_pin_point") &&
                check(ent_scene_attach_mesentery(scene, organ_id), "ent_scene_attach_mesentery") &&
                check(ent_scene_step(scene, 1e-3), "first ent_scene_step");
    // The organ's surface as a target for the exposure query, seen from above.
    ent_exposure_desc target;
    ent_exposure_desc_default(&target);
    target.points_xyz_m = vertices;
    target.point_count = 8;
    target.triangles = triangles;
    target.triangle_count = 12;
    target.obstacle = organ_id;
    ent_exposure* exposure = nullptr;
    double spans[2 * 8], seen[12];
    ent_exposure_result exposed;
    std::memset(&exposed, 0, sizeof exposed);
    exposed.struct_size = sizeof exposed;
    exposed.span_capacity = 8;
    exposed.spans_u = spans;
    exposed.element_visible = seen;
    const double eye[3] = {0.0, 0.0, 0.4};
    if (made && !check(ent_exposure_create(scene, &target, &exposure), "ent_exposure_create")) made = false;
    if (made) {
        double position[3] = {0.1, 0.0, 0.0}, orientation[4] = {1.0, 0.0, 0.0, 0.0};
        const double linear[3] = {0.0, 0.0, 0.1}, angular[3] = {0.0, 0.0, 0.0};
        double tilted[3] = {0.0, 0.0, -9.81};
        uint32_t count = 0;
        alloc_counter_start();
        bool ok = true;
        for (int i = 0; i < 200 && ok; ++i) {
            position[2] += 1e-4;  // 2 cm up in 200 steps, into the bowel
            tilted[0] += 0.01;    // the table tilting, from the 100th step
            ok = check(ent_obstacle_set_pose(scene, organ_id, position, orientation), "ent_obstacle_set_pose") &&
                 (i % 50 != 0 ||
                  check(ent_obstacle_set_velocity(scene, organ_id, linear, angular), "ent_obstacle_set_velocity")) &&
                 (i < 100 || check(ent_scene_set_gravity(scene, tilted), "ent_scene_set_gravity")) &&
                 check(ent_scene_step(scene, 1e-3), "ent_scene_step") &&
                 check(ent_obstacle_pose(scene, organ_id, position, orientation), "ent_obstacle_pose") &&
                 check(ent_scene_obstacle_count(scene, &count), "ent_scene_obstacle_count") &&
                 check(ent_scene_exposure(scene, exposure, eye, &exposed), "ent_scene_exposure");
        }
        const unsigned long in_steps = alloc_counter_stop();
        if (ok) report("200 steps, moving mesh organ, exposure", name, in_steps);
        // Friction and pins change the stability bounds and the mass matrix's factor, so
        // they allocate (between steps, rarely); the steps after them do not.
        ok = ok && check(ent_obstacle_set_friction(scene, organ_id, 0.5), "ent_obstacle_set_friction") &&
             check(ent_scene_unpin_point(scene, desc.control_points - 1), "ent_scene_unpin_point") &&
             check(ent_scene_step(scene, 1e-3), "ent_scene_step");
        alloc_counter_start();
        for (int i = 0; i < 50 && ok; ++i) ok = check(ent_scene_step(scene, 1e-3), "ent_scene_step");
        const unsigned long after = alloc_counter_stop();
        if (ok) report("50 steps after unpinning", name, after);
    }
    ent_exposure_destroy(exposure);
    ent_scene_destroy(scene);
}

// A clamped end on an organ that turns at every step (issue 20): the clamp's direction and
// rate change before every step, and the explicit path factors its mass matrix again.
void run_clamped_on_turning_organ(int32_t integrator, const char* name) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.integrator = integrator;
    desc.length_m = 0.5;
    desc.control_points = 20;
    desc.shape = ENT_SHAPE_LINE;
    desc.clamped_ends = ENT_PIN_FIRST;
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    ent_scene* scene = nullptr;
    if (!check(ent_scene_create(&desc, &scene), "ent_scene_create")) return;
    ent_obstacle_desc organ;
    ent_obstacle_desc_default(&organ);
    organ.kind = ENT_OBSTACLE_SPHERE;
    organ.center_m[2] = 0.3;  // clear of the bowel
    organ.radius_m = 0.03;
    int32_t organ_id = -1;
    const bool made = check(ent_scene_add_obstacle(scene, &organ, &organ_id), "ent_scene_add_obstacle") &&
                      check(ent_scene_attach_clamped_end(scene, ENT_PIN_FIRST, organ_id), "ent_scene_attach_clamped_end") &&
                      check(ent_scene_step(scene, 1e-3), "first ent_scene_step");
    if (made) {
        const double position[3] = {0.0, 0.0, 0.0};
        alloc_counter_start();
        bool ok = true;
        for (int i = 1; i <= 200 && ok; ++i) {
            const double angle = 0.002 * i;  // about z
            const double orientation[4] = {std::cos(angle / 2), 0.0, 0.0, std::sin(angle / 2)};
            ok = check(ent_obstacle_set_pose(scene, organ_id, position, orientation), "ent_obstacle_set_pose") &&
                 check(ent_scene_step(scene, 1e-3), "ent_scene_step");
        }
        const unsigned long in_steps = alloc_counter_stop();
        if (ok) report("200 steps, a clamped end on a turning organ", name, in_steps);
    }
    ent_scene_destroy(scene);
}

}  // namespace

int main() {
    std::printf("no allocation after the first step (default scene + mesentery + damping + "
                "self-collision, in a box, with a tool):\n");
    std::fflush(stdout);
    // The counter must see allocations at all, or a passing run would prove nothing.
    // (Stored through a volatile pointer so the compiler cannot drop the pairs.)
    alloc_counter_start();
    void* probe = ::operator new(64);
    keep = probe;
    void* probe_c = std::malloc(64);
    keep = probe_c;
    const unsigned long probes = alloc_counter_stop();
    ::operator delete(probe);
    std::free(probe_c);
    if (probes != 2) {
        std::printf("the allocation counter saw %lu of 2 probe allocations\n", probes);
        return 1;
    }
    // The explicit integrators take many substeps with contacts: a 1 m bowel keeps them quick.
    run(ENT_INTEGRATOR_RK4, "rk4 (1 m)", 1.0, 40);
    run(ENT_INTEGRATOR_SYMPLECTIC_EULER, "symplectic (1 m)", 1.0, 40);
    run(ENT_INTEGRATOR_IMPLICIT_EULER, "implicit_euler", 6.0, 240);
    run(ENT_INTEGRATOR_BDF2, "bdf2", 6.0, 240);
    // Clamped ends change every solve (clamped_ends.h): the implicit and the explicit path.
    run(ENT_INTEGRATOR_BDF2, "bdf2, both ends clamped", 6.0, 240, ENT_PIN_BOTH);
    run(ENT_INTEGRATOR_SYMPLECTIC_EULER, "symplectic, clamped (1 m)", 1.0, 40, ENT_PIN_BOTH);
    run_moving_anatomy();
    run_clamped_on_turning_organ(ENT_INTEGRATOR_IMPLICIT_EULER, "implicit_euler");
    run_clamped_on_turning_organ(ENT_INTEGRATOR_RK4, "rk4");
    if (failures != 0) {
        std::printf("%d failure(s)\n", failures);
        return 1;
    }
    std::printf("no allocation found\n");
    return 0;
}
