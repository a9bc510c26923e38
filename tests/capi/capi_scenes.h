// SPDX-License-Identifier: Apache-2.0
// The scenes the C API tests build again and again, written once. Through enteron.h only.
#pragma once

#include <cmath>

#include "capi_test_support.h"

namespace capi_test {

constexpr double kBowelRadius = 0.0125;  // the default R, m

// A straight bowel along x, centred on the origin, lying on the plane z = 0 (its axis R
// above it, or `axis_height_m`): the default stiffnesses, damping, gravity and friction
// unless `effects` names others; settled for `settle_s` seconds in steps of `dt_s` before
// it is handed over (0: not stepped).
struct BowelOnPlane {
    double length_m = 0.4;
    uint32_t control_points = 17;
    int32_t integrator = ENT_INTEGRATOR_IMPLICIT_EULER;
    int32_t clamped_ends = ENT_PIN_NONE;
    double axis_height_m = kBowelRadius;
    uint32_t effects = 0;  // ENT_EFFECT_BIT(...) | ...; 0: the defaults
    double settle_s = 0.0;
    double dt_s = 1e-3;
};

inline ScenePtr bowel_on_plane(const BowelOnPlane& bowel) {
    ent_scene_desc desc = default_desc();
    desc.integrator = bowel.integrator;
    desc.clamped_ends = bowel.clamped_ends;
    desc.length_m = bowel.length_m;
    desc.control_points = bowel.control_points;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_center_m[0] = -0.5 * bowel.length_m;
    desc.shape_center_m[2] = bowel.axis_height_m;
    if (bowel.effects != 0) desc.effects = bowel.effects;
    ScenePtr scene = create(desc);
    if (!scene) return scene;
    ent_obstacle_desc plane;
    ent_obstacle_desc_default(&plane);
    plane.kind = ENT_OBSTACLE_PLANE;
    EXPECT_EQ(ent_scene_add_obstacle(scene.get(), &plane, nullptr), ENT_OK) << ent_last_error();
    const int settle_steps = int(std::lround(bowel.settle_s / bowel.dt_s));
    if (settle_steps > 0) {
        EXPECT_TRUE(step_n(scene.get(), bowel.dt_s, settle_steps));  // settle
    }
    return scene;
}

}  // namespace capi_test
