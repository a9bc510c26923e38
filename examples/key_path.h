/* SPDX-License-Identifier: Apache-2.0 */
/*
 * A path given by keys: a point that moves linearly from key to key in time, as a haptic
 * device's recording or a retractor's motion would, and an organ moved along one. Plain C99 (the viewer includes it from
 * C++); shared by the examples that drive a tool or an organ along a path.
 */
#ifndef ENTERON_EXAMPLES_KEY_PATH_H
#define ENTERON_EXAMPLES_KEY_PATH_H

#include <stddef.h>

#include <enteron/enteron.h>

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

/* Moves an obstacle to its pose at time t: where it started plus the path's offset at t,
 * its orientation kept (a retractor lifting an organ). Call it before the step that ends
 * at t. */
static inline ent_status obstacle_follow_path(ent_scene* scene, int32_t obstacle, const double start_m[3],
                                              const double orientation_wxyz[4], const double* keys, size_t count,
                                              double t) {
    double offset[3], position[3];
    int c;
    path_at(keys, count, t, offset);
    for (c = 0; c < 3; ++c) position[c] = start_m[c] + offset[c];
    return ent_obstacle_set_pose(scene, obstacle, position, orientation_wxyz);
}

#endif
