/* SPDX-License-Identifier: Apache-2.0 */
/*
 * A program outside the project that uses an installed libenteron, the way a simulator
 * vendor would: only <enteron/enteron.h> and -lenteron. Built by run_consumer_test.sh
 * twice, once through the CMake package (find_package) and once through pkg-config.
 * Exit status 0 when the library loads, matches the header's major version, creates a
 * scene from JSON, steps it and returns a finite axis; 1 otherwise.
 */
#include <enteron/enteron.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#define AXIS_POINTS 50
#define STEPS 10

static int fail(const char* what, ent_status status) {
    fprintf(stderr, "consumer: %s failed: %s (%s)\n", what, ent_status_string(status),
            ent_last_error());
    return 1;
}

int main(void) {
    static const char json[] =
        "{\"intestine\": {\"length\": 1.0, \"radius\": 0.0125, \"control_points\": 40,"
        "  \"linear_density\": 0.3, \"stretch_stiffness\": 100, \"bend_stiffness\": 2.5e-3,"
        "  \"shape\": {\"kind\": \"helix\", \"center\": [0, 0, 0],"
        "             \"helix_radius\": 0.05, \"helix_pitch\": 0.03}},"
        " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},"
        " \"gravity\": [0, 0, -9.81]}";
    const uint32_t version = ent_version();
    ent_scene* scene = NULL;
    ent_status status;
    ent_stats stats;
    double axis[AXIS_POINTS * 3];
    int i;

    if ((version >> 16) != ENT_VERSION_MAJOR) {
        fprintf(stderr, "consumer: library major version %u, header major version %d\n",
                (unsigned)(version >> 16), ENT_VERSION_MAJOR);
        return 1;
    }

    status = ent_scene_create_json(json, strlen(json), &scene);
    if (status != ENT_OK) return fail("ent_scene_create_json", status);

    for (i = 0; i < STEPS; ++i) {
        status = ent_scene_step(scene, 0.001);
        if (status != ENT_OK) {
            fail("ent_scene_step", status);
            ent_scene_destroy(scene);
            return 1;
        }
    }

    status = ent_scene_axis(scene, AXIS_POINTS, axis);
    if (status != ENT_OK) {
        fail("ent_scene_axis", status);
        ent_scene_destroy(scene);
        return 1;
    }
    for (i = 0; i < AXIS_POINTS * 3; ++i) {
        if (!isfinite(axis[i])) {
            fprintf(stderr, "consumer: axis coordinate %d is not finite\n", i);
            ent_scene_destroy(scene);
            return 1;
        }
    }

    memset(&stats, 0, sizeof stats);
    stats.struct_size = sizeof stats;
    status = ent_scene_stats(scene, &stats);
    if (status != ENT_OK) {
        fail("ent_scene_stats", status);
        ent_scene_destroy(scene);
        return 1;
    }
    if (stats.steps != STEPS) {
        fprintf(stderr, "consumer: stats report %llu steps, expected %d\n",
                (unsigned long long)stats.steps, STEPS);
        ent_scene_destroy(scene);
        return 1;
    }

    ent_scene_destroy(scene);
    printf("consumer: ok with libenteron %u.%u.%u (header %d.%d.%d), time %.3f s, "
           "first axis point (%.4f, %.4f, %.4f) m\n",
           (unsigned)(version >> 16), (unsigned)((version >> 8) & 0xffu),
           (unsigned)(version & 0xffu), ENT_VERSION_MAJOR, ENT_VERSION_MINOR,
           ENT_VERSION_PATCH, stats.time_s, axis[0], axis[1], axis[2]);
    return 0;
}
