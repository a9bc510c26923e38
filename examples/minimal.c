/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The smallest complete Enteron program: create a scene from JSON, step it for one
 * simulated second, read the axis, print one line. Every status is checked.
 *
 *   enteron_minimal     prints "minimal: t = 1.000 s, 100 axis points, first end at
 *                       (-0.0833, 0.1158, -0.1538) m, lowest point z = -0.2492 m"
 */
#include <enteron/enteron.h>

#include <stdio.h>
#include <string.h>

#define AXIS_POINTS 100

int main(void) {
    static const char json[] =
        "{\"intestine\": {\"length\": 1.0, \"control_points\": 40,"
        "                 \"stretch_stiffness\": 100, \"bend_stiffness\": 2.5e-3},"
        " \"gravity\": [0, 0, -9.81], \"damping\": {}, \"mesentery\": {}}";
    ent_scene* scene = NULL;
    ent_stats stats;
    double axis[AXIS_POINTS * 3];
    double lowest;
    int i;

    if ((ent_version() >> 16) != ENT_VERSION_MAJOR) {
        fprintf(stderr, "minimal: libenteron has major version %u, this program needs %d\n",
                (unsigned)(ent_version() >> 16), ENT_VERSION_MAJOR);
        return 1;
    }
    if (ent_scene_create_json(json, strlen(json), &scene) != ENT_OK) {
        fprintf(stderr, "minimal: %s\n", ent_last_error());
        return 1;
    }
    for (i = 0; i < 1000; ++i) { /* one simulated second in 1 ms steps */
        if (ent_scene_step(scene, 0.001) != ENT_OK) {
            fprintf(stderr, "minimal: step %d: %s\n", i, ent_last_error());
            ent_scene_destroy(scene);
            return 1;
        }
    }
    memset(&stats, 0, sizeof stats);
    stats.struct_size = sizeof stats;
    if (ent_scene_axis(scene, AXIS_POINTS, axis) != ENT_OK || ent_scene_stats(scene, &stats) != ENT_OK) {
        fprintf(stderr, "minimal: %s\n", ent_last_error());
        ent_scene_destroy(scene);
        return 1;
    }
    lowest = axis[2];
    for (i = 1; i < AXIS_POINTS; ++i)
        if (axis[3 * i + 2] < lowest) lowest = axis[3 * i + 2];
    printf("minimal: t = %.3f s, %d axis points, first end at (%.4f, %.4f, %.4f) m, lowest point z = %.4f m\n",
           stats.time_s, AXIS_POINTS, axis[0], axis[1], axis[2], lowest);
    ent_scene_destroy(scene);
    return 0;
}
