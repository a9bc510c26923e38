/* SPDX-License-Identifier: Apache-2.0 */
/*
 * enteron_abdomen: the 6 m small bowel in an abdomen made of organ meshes
 * (examples/scenes/abdomen.json: the abdominal wall, a liver and a stomach, the mesentery's
 * root along the posterior wall), a retractor that lifts the liver and a grasper that goes
 * down into the bowel. docs/anatomy.md describes the scene.
 *
 * Loads the scene file (its meshes are found next to it), lets the bowel settle for 1 s,
 * lifts the liver 4 cm anteriorly in 0.5 s (ent_obstacle_set_pose before every step, as a
 * simulator's retractor would), lowers the tool into the bowel (abdomen_motion.h, the
 * motion enteron_demo and enteron-viewer play on this scene too), and prints one line per
 * simulated half second: where the liver is, the bowel's lowest and highest point, its
 * contacts and their deepest penetration. Fails (exit 1) if a call fails or the bowel
 * leaves the cavity.
 *
 * Usage: enteron_abdomen [SCENE] (default examples/scenes/abdomen.json)
 */
#include <enteron/enteron.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "abdomen_motion.h"

#define STEP_S 0.001
#define LIVER ABDOMEN_LIVER
#define SECONDS 3.0

static int failed(const char* call, ent_status status) {
    fprintf(stderr, "enteron_abdomen: %s: %s: %s\n", call, ent_status_string(status), ent_last_error());
    return 1;
}

int main(int argc, char** argv) {
    const char* path = argc > 1 ? argv[1] : "examples/scenes/abdomen.json";
    ent_scene* scene = NULL;
    ent_status status = ent_scene_create_json_file(path, NULL, &scene);
    if (status != ENT_OK) return failed("ent_scene_create_json_file", status);

    uint32_t obstacles = 0, count = 0;
    double liver_at[3], orientation[4];
    status = ent_scene_obstacle_count(scene, &obstacles);
    if (status == ENT_OK) status = ent_obstacle_pose(scene, LIVER, liver_at, orientation);
    if (status == ENT_OK) status = ent_scene_control_points(scene, 0, NULL, &count);
    if (status != ENT_OK) return failed("the scene's queries", status);
    printf("%s: %u obstacles, %u control points\n", path, obstacles, count);

    double* points = malloc(3 * (size_t)count * sizeof(double));
    if (points == NULL) return 1;
    int code = 0;
    const int steps = (int)lround(SECONDS / STEP_S);
    for (int i = 1; i <= steps && code == 0; ++i) {
        const double t = i * STEP_S;
        /* The retractor and the grasper (abdomen_motion.h). */
        double tip[3];
        status = obstacle_follow_path(scene, LIVER, liver_at, orientation, abdomen_liver_keys, ABDOMEN_LIVER_KEY_COUNT, t);
        if (status != ENT_OK) return failed("ent_obstacle_set_pose", status);
        path_at(abdomen_tool_keys, ABDOMEN_TOOL_KEY_COUNT, t, tip);
        const double upright[4] = {1.0, 0.0, 0.0, 0.0};
        status = ent_tool_set_pose(scene, 0, tip, upright);
        if (status == ENT_OK) status = ent_scene_step(scene, STEP_S);
        if (status != ENT_OK) return failed("ent_scene_step", status);
        if (i % 500 != 0) continue;
        ent_stats stats;
        memset(&stats, 0, sizeof stats);
        stats.struct_size = sizeof stats;
        double pose[3], q[4];
        status = ent_scene_stats(scene, &stats);
        if (status == ENT_OK) status = ent_obstacle_pose(scene, LIVER, pose, q);
        if (status == ENT_OK) status = ent_scene_control_points(scene, count, points, &count);
        if (status != ENT_OK) return failed("the queries", status);
        double low = INFINITY, high = -INFINITY;
        for (uint32_t k = 0; k < count; ++k) {
            low = fmin(low, points[3 * k + 2]);
            high = fmax(high, points[3 * k + 2]);
        }
        printf("t = %.1f s: liver at z = %+.3f m, bowel z from %+.3f to %+.3f m, %u contacts, deepest %.2f mm\n",
               stats.time_s, pose[2], low, high, stats.contacts, 1e3 * stats.max_penetration_m);
        /* The cavity's floor is at z = -0.17 m: a bowel below it has left the abdomen. */
        if (!(low > -0.17) || !(high < 0.17)) {
            fprintf(stderr, "enteron_abdomen: the bowel left the cavity\n");
            code = 1;
        }
    }
    free(points);
    ent_scene_destroy(scene);
    return code;
}
