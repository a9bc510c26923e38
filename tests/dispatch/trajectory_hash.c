/* SPDX-License-Identifier: Apache-2.0 */
/* Prints a hash of the bits of a pile's trajectory: the 6 m bowel (N = 120) dropped into a
 * box with self-contact, then pushed by a sweeping tool, implicit Euler, 1 ms steps. Every
 * hot kernel of a step runs (band updates, factorisation, solve, sphere placement, contact
 * blocks). dispatch.same_bits runs it on this build's library and on a baseline-only build
 * (ENTERON_CPU_DISPATCH=OFF) and compares: the x86-64-v3 kernels must give the same bits. */
#include <enteron/enteron.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

enum { kPoints = 120, kDropSteps = 1500, kToolSteps = 500 };

static uint64_t mix(uint64_t hash, const double* values, size_t count) {
    for (size_t k = 0; k < count; ++k) {
        uint64_t bits;
        memcpy(&bits, &values[k], sizeof bits);
        hash = (hash ^ bits) * 1099511628211ull; /* FNV-1a over 64-bit words */
    }
    return hash;
}

static int fail(const char* call, ent_status status) {
    fprintf(stderr, "trajectory_hash: %s: %s: %s\n", call, ent_status_string(status), ent_last_error());
    return 1;
}

int main(void) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                   ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    desc.length_m = 6.0;
    desc.radius_m = 0.0125;
    desc.control_points = kPoints;
    desc.shape = ENT_SHAPE_HELIX;
    desc.shape_center_m[2] = -0.13;
    desc.shape_helix_radius_m = 0.1;
    desc.shape_helix_pitch_m = 0.025;
    desc.integrator = ENT_INTEGRATOR_IMPLICIT_EULER;
    desc.timestep_s = 1e-3;
    desc.pinned_ends = ENT_PIN_NONE;
    ent_scene* scene = NULL;
    ent_status status = ent_scene_create(&desc, &scene);
    if (status != ENT_OK) return fail("ent_scene_create", status);
    ent_obstacle_desc box;
    ent_obstacle_desc_default(&box);
    box.kind = ENT_OBSTACLE_BOX_INSIDE;
    for (int c = 0; c < 3; ++c) box.half_extents_m[c] = 0.15;
    status = ent_scene_add_obstacle(scene, &box, NULL);
    if (status != ENT_OK) return fail("ent_scene_add_obstacle", status);
    uint64_t hash = 1469598103934665603ull;
    double points[3 * kPoints];
    uint32_t count = 0;
    for (int step = 0; step < kDropSteps; ++step) {
        if ((status = ent_scene_step(scene, 1e-3)) != ENT_OK) return fail("ent_scene_step", status);
        ent_scene_control_points(scene, kPoints, points, &count);
        hash = mix(hash, points, 3 * kPoints);
    }
    /* A tool comes down on the highest point and sweeps along x. */
    size_t top = 0;
    for (size_t i = 0; i < kPoints; ++i)
        if (points[3 * i + 2] > points[3 * top + 2]) top = i;
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    for (int c = 0; c < 3; ++c) tool.position_m[c] = points[3 * top + c];
    tool.position_m[2] += desc.radius_m + tool.radius_m - 0.005;
    int32_t id = -1;
    if ((status = ent_tool_add(scene, &tool, &id)) != ENT_OK) return fail("ent_tool_add", status);
    const double upright[4] = {1.0, 0.0, 0.0, 0.0};
    for (int step = 0; step < kToolSteps; ++step) {
        double position[3] = {tool.position_m[0] + 0.02 * sin(0.01 * step), tool.position_m[1], tool.position_m[2]};
        if ((status = ent_tool_set_pose(scene, id, position, upright)) != ENT_OK) return fail("ent_tool_set_pose", status);
        if ((status = ent_scene_step(scene, 1e-3)) != ENT_OK) return fail("ent_scene_step", status);
        double force[3], torque[3];
        ent_scene_control_points(scene, kPoints, points, &count);
        ent_tool_wrench(scene, id, force, torque);
        hash = mix(hash, points, 3 * kPoints);
        hash = mix(hash, force, 3);
    }
    ent_scene_destroy(scene);
    printf("%016llx\n", (unsigned long long)hash);
    return 0;
}
