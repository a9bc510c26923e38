/* SPDX-License-Identifier: Apache-2.0 */
/* The C API from plain C99: create (from a desc and from JSON), step, axis, control points,
 * stats, effect stats, destroy, and a few failures. Prints what went wrong and returns
 * non-zero on any failure. */
#include <enteron/enteron.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

#define CHECK(condition)                                                                   \
    do {                                                                                   \
        if (!(condition)) {                                                                \
            fprintf(stderr, "%s:%d: check failed: %s (last error: %s)\n", __FILE__, __LINE__, \
                    #condition, ent_last_error());                                        \
            ++failures;                                                                    \
        }                                                                                  \
    } while (0)

#define CHECK_STATUS(call, expected)                                                        \
    do {                                                                                    \
        ent_status status_ = (call);                                                        \
        if (status_ != (expected)) {                                                        \
            fprintf(stderr, "%s:%d: %s returned %d (%s), expected %d (last error: %s)\n",     \
                    __FILE__, __LINE__, #call, (int)status_, ent_status_string(status_),    \
                    (int)(expected), ent_last_error());                                     \
            ++failures;                                                                     \
        }                                                                                   \
    } while (0)

static void exercise(ent_scene* scene, uint32_t expected_points) {
    enum { kSamples = 50 };
    double axis[kSamples * 3];
    double points[64 * 3];
    uint32_t count = 0;
    ent_stats stats;
    ent_effect_stats effect;
    int i;

    CHECK_STATUS(ent_scene_control_points(scene, 0, NULL, &count), ENT_OK);
    CHECK(count == expected_points);
    for (i = 0; i < 100; ++i) CHECK_STATUS(ent_scene_step(scene, 1e-3), ENT_OK);

    CHECK_STATUS(ent_scene_axis(scene, kSamples, axis), ENT_OK);
    for (i = 0; i < kSamples * 3; ++i) CHECK(isfinite(axis[i]));
    CHECK_STATUS(ent_scene_control_points(scene, 64, points, &count), ENT_OK);
    CHECK(count == expected_points);
    /* The axis passes through the end control points. */
    CHECK(fabs(axis[0] - points[0]) < 1e-12 && fabs(axis[2] - points[2]) < 1e-12);
    CHECK(fabs(axis[3 * (kSamples - 1) + 2] - points[3 * (count - 1) + 2]) < 1e-12);

    memset(&stats, 0, sizeof stats);
    stats.struct_size = sizeof stats;
    CHECK_STATUS(ent_scene_stats(scene, &stats), ENT_OK);
    CHECK(stats.steps == 100);
    CHECK(stats.control_points == expected_points);
    CHECK(fabs(stats.time_s - 0.1) < 1e-12);
    CHECK(stats.substeps >= 100);
    CHECK(stats.kinetic_energy_J > 0.0); /* it is falling */

    memset(&effect, 0, sizeof effect);
    effect.struct_size = sizeof effect;
    CHECK_STATUS(ent_scene_effect_stats(scene, ENT_EFFECT_GRAVITY, &effect), ENT_OK);
    CHECK(effect.enabled == 1 && effect.calls >= 100);
    CHECK_STATUS(ent_scene_effect_stats(scene, ENT_EFFECT_MESENTERY, &effect), ENT_OK);
    CHECK(effect.enabled == 0 && effect.calls == 0);
    CHECK_STATUS(ent_scene_effect_stats(scene, 42, &effect), ENT_ERROR_NOT_FOUND);

    /* Failures change nothing and say why. */
    CHECK_STATUS(ent_scene_step(scene, 0.0), ENT_ERROR_INVALID_ARGUMENT);
    CHECK(strlen(ent_last_error()) > 0);
    CHECK_STATUS(ent_scene_axis(scene, 1, axis), ENT_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(ent_scene_control_points(scene, 1, points, &count), ENT_ERROR_BUFFER_TOO_SMALL);
    CHECK(count == expected_points);
    CHECK_STATUS(ent_scene_stats(scene, &stats), ENT_OK);
    CHECK(stats.steps == 100);
}

int main(void) {
    ent_scene_desc desc;
    ent_scene* scene = NULL;
    static const char json[] =
        "{\"intestine\": {\"length\": 1.0, \"control_points\": 25, \"stretch_stiffness\": 100,"
        " \"bend_stiffness\": 0.0025, \"shape\": {\"kind\": \"serpentine\", \"leg_length\": 0.2}},"
        " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},"
        " \"gravity\": [0, 0, -9.81], \"damping\": {\"drag\": 0.05}}";

    if ((ent_version() >> 16) != ENT_VERSION_MAJOR) {
        fprintf(stderr, "library major version %u, header %d\n", (unsigned)(ent_version() >> 16),
                ENT_VERSION_MAJOR);
        return 1;
    }

    ent_scene_desc_default(&desc);
    desc.control_points = 40;
    desc.length_m = 1.5;
    CHECK_STATUS(ent_scene_create(&desc, &scene), ENT_OK);
    if (scene != NULL) {
        exercise(scene, 40);
        ent_scene_destroy(scene);
    }

    scene = NULL;
    CHECK_STATUS(ent_scene_create_json(json, strlen(json), &scene), ENT_OK);
    if (scene != NULL) {
        exercise(scene, 25);
        ent_scene_destroy(scene);
    }

    scene = NULL;
    desc.radius_m = -1.0;
    CHECK_STATUS(ent_scene_create(&desc, &scene), ENT_ERROR_INVALID_ARGUMENT);
    CHECK(scene == NULL);
    CHECK(strstr(ent_last_error(), "radius_m") != NULL);
    CHECK_STATUS(ent_scene_create_json("{", 1, &scene), ENT_ERROR_PARSE);
    CHECK(scene == NULL);
    CHECK_STATUS(ent_scene_step(NULL, 1e-3), ENT_ERROR_INVALID_ARGUMENT);
    ent_scene_destroy(NULL);

    if (failures != 0) {
        fprintf(stderr, "%d check(s) failed\n", failures);
        return 1;
    }
    printf("C API from C99: all checks passed\n");
    return 0;
}
