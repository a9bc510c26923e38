/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The demo scene, shared by enteron_demo (demo.c) and enteron-viewer: a 6 m small bowel
 * dropped into the abdominal cavity, held by its mesentery, and the path of the tool that
 * pushes it aside; and the motions the demo and the viewer play on their scenes (the demo
 * scene's tool path, the abdomen scene's retractor and grasper, abdomen_motion.h). Plain
 * C99 (the viewer includes it from C++).
 *
 * No pinned ends: the bowel is dropped freely into the abdominal cavity (the inside of a
 * 30 cm box), its folds pile up on each other (self-collision) and its mesentery
 * (tension-only springs to a 15 cm root along x at z = 0) holds it up. The helix starts
 * near the floor, so the root runs through the coil.
 */
#ifndef ENTERON_EXAMPLES_DEMO_SCENE_H
#define ENTERON_EXAMPLES_DEMO_SCENE_H

#include <stddef.h>
#include <string.h>

#include "abdomen_motion.h"
#include "key_path.h"

static const char demo_scene_json[] =
    "{\n"
    "  \"intestine\": {\n"
    "    \"length\": 6.0,\n"
    "    \"radius\": 0.0125,\n"
    "    \"control_points\": 240,\n"
    "    \"linear_density\": 0.3,\n"
    "    \"stretch_stiffness\": 100,\n"
    "    \"bend_stiffness\": 2.5e-3,\n"
    "    \"shape\": {\"kind\": \"helix\", \"center\": [0, 0, -0.13],\n"
    "              \"helix_radius\": 0.1, \"helix_pitch\": 0.025}\n"
    "  },\n"
    "  \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},\n"
    "  \"gravity\": [0, 0, -9.81],\n"
    "  \"damping\": {\"drag\": 0.05, \"stretch\": 0.05, \"bend\": 0},\n"
    "  \"mesentery\": {\"root\": [[-0.075, 0, 0], [0.075, 0, 0]],\n"
    "                \"stiffness\": 5, \"attachments\": 60, \"rest_length\": 0},\n"
    "  \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0],\n"
    "                    \"half_extents\": [0.15, 0.15, 0.15]}],\n"
    "  \"self_collision\": {},\n"
    "  \"tools\": [{\"radius\": 0.005, \"length\": 0.3, \"max_force\": 5,\n"
    "              \"position\": [-0.1, 0, 0.3], \"orientation\": [1, 0, 0, 0]}]\n"
    "}\n";

/* The tool's tip along the demo, 4 doubles per key (t_s, x, y, z in m): a vertical grasper
 * waiting above the cavity while the bowel settles, down into the pile (2 to 2.6 s),
 * across the cavity along +x (2.6 to 4 s), and up again (4 to 4.6 s). */
static const double demo_tool_keys[] = {0.0, -0.1, 0.0, 0.3,
                                        2.0, -0.1, 0.0, 0.3,
                                        2.6, -0.1, 0.0, -0.08,
                                        4.0, 0.1, 0.0, -0.08,
                                        4.6, 0.1, 0.0, 0.3};
#define DEMO_TOOL_KEY_COUNT (sizeof demo_tool_keys / (4 * sizeof demo_tool_keys[0]))

/* What drives a scene over time, as a simulator's hands and retractors would: tool 0's tip
 * along tool_keys (t_s, x, y, z in m), and one obstacle (-1: none) displaced from its pose
 * in the scene along obstacle_keys (t_s, dx, dy, dz in m). */
typedef struct demo_motion {
    const char* name;               /* "demo", "abdomen": enteron-viewer --script NAME */
    const char* scene_file;         /* the scene file it belongs to (its base name), or NULL: the demo scene */
    const double* tool_keys;
    size_t tool_key_count;
    int obstacle;
    const double* obstacle_keys;
    size_t obstacle_key_count;
} demo_motion;

static const demo_motion demo_motions[] = {
    {"demo", NULL, demo_tool_keys, DEMO_TOOL_KEY_COUNT, -1, NULL, 0},
    {"abdomen", "abdomen.json", abdomen_tool_keys, ABDOMEN_TOOL_KEY_COUNT, ABDOMEN_LIVER, abdomen_liver_keys,
     ABDOMEN_LIVER_KEY_COUNT}};
#define DEMO_MOTION_COUNT (sizeof demo_motions / sizeof demo_motions[0])

/* The motion called name, or NULL. */
static inline const demo_motion* demo_motion_named(const char* name) {
    size_t i;
    for (i = 0; i < DEMO_MOTION_COUNT; ++i)
        if (strcmp(demo_motions[i].name, name) == 0) return &demo_motions[i];
    return NULL;
}

/* The motion of a scene: NULL path (the demo scene) gives the demo's; a file whose base
 * name is a motion's scene_file (examples/scenes/abdomen.json) gives that one; any other
 * file NULL. */
static inline const demo_motion* demo_motion_for_scene(const char* path) {
    const char* base;
    size_t i;
    if (path == NULL) return &demo_motions[0];
    base = strrchr(path, '/');
    base = base != NULL ? base + 1 : path;
    for (i = 0; i < DEMO_MOTION_COUNT; ++i)
        if (demo_motions[i].scene_file != NULL && strcmp(demo_motions[i].scene_file, base) == 0)
            return &demo_motions[i];
    return NULL;
}

#endif
