/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The motion of the abdomen scene (examples/scenes/abdomen.json), in one place for
 * enteron_abdomen (abdomen.c), enteron_demo --scene and enteron-viewer: a retractor lifts
 * the liver 4 cm anteriorly between 1 and 1.5 s, after the bowel has settled, and a
 * vertical grasper goes down from above the cavity into the coils of the bowel, to 6 cm
 * above the floor, between 1.5 and 2.5 s (it pushes them with up to about 4.7 N, below its
 * max_force). Plain C99 (the viewer includes it from C++).
 */
#ifndef ENTERON_EXAMPLES_ABDOMEN_MOTION_H
#define ENTERON_EXAMPLES_ABDOMEN_MOTION_H

#include "key_path.h"

/* The liver: obstacle 1 in the file's order (wall, liver, stomach). */
#define ABDOMEN_LIVER 1

/* The liver's displacement from its pose in the scene file, 4 doubles per key (t_s, dx,
 * dy, dz in m): held while the bowel settles, then lifted along +z (anterior). */
static const double abdomen_liver_keys[] = {0.0, 0.0, 0.0, 0.0,
                                            1.0, 0.0, 0.0, 0.0,
                                            1.5, 0.0, 0.0, 0.04};
#define ABDOMEN_LIVER_KEY_COUNT (sizeof abdomen_liver_keys / (4 * sizeof abdomen_liver_keys[0]))

/* The grasper's tip, 4 doubles per key (t_s, x, y, z in m): from where the scene file puts
 * it, 4 cm across in the air, then down. */
static const double abdomen_tool_keys[] = {0.0, -0.1, -0.05, 0.3,
                                           1.5, -0.06, -0.05, 0.3,
                                           2.5, -0.06, -0.05, -0.11};
#define ABDOMEN_TOOL_KEY_COUNT (sizeof abdomen_tool_keys / (4 * sizeof abdomen_tool_keys[0]))

#endif
