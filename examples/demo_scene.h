/*
 * The demo scene, shared by enteron_demo (demo.c) and enteron-viewer: a 6 m small bowel
 * dropped into the abdominal cavity, held by its mesentery, and the path of the tool that
 * pushes it aside. Plain C99 (the viewer includes it from C++).
 *
 * No pinned ends: the bowel is dropped freely into the abdominal cavity (the inside of a
 * 30 cm box), its folds pile up on each other (self-collision) and its mesentery
 * (tension-only springs to a 15 cm root along x at z = 0) holds it up. The helix starts
 * near the floor, so the root runs through the coil.
 */
#ifndef ENTERON_EXAMPLES_DEMO_SCENE_H
#define ENTERON_EXAMPLES_DEMO_SCENE_H

#include <stddef.h>

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

/* The point at time t of a path given by count keys t_s, x, y, z (4 doubles each, sorted
 * by time): linear between keys, held before the first and after the last. */
static inline void path_at(const double* keys, size_t count, double t, double out[3]) {
    size_t k;
    int c;
    for (k = 1; k < count && t > keys[4 * k]; ++k) {
    }
    if (count == 1 || t <= keys[0]) {
        for (c = 0; c < 3; ++c) out[c] = keys[c + 1];
    } else if (k == count) {
        for (c = 0; c < 3; ++c) out[c] = keys[4 * (count - 1) + c + 1];
    } else {
        const double* a = &keys[4 * (k - 1)];
        const double* b = &keys[4 * k];
        const double f = (t - a[0]) / (b[0] - a[0]);
        for (c = 0; c < 3; ++c) out[c] = (1.0 - f) * a[c + 1] + f * b[c + 1];
    }
}

#endif
