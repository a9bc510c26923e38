// SPDX-License-Identifier: Apache-2.0
// The bdf2 integrator through the C API: second order also when dt changes from step to step
// (its variable-step coefficients), and no energy from nothing. Its constant-step order is in
// test_convergence.cpp, its rolled-back history in tests/unit/mechanics/test_bdf2.cpp.
#include "capi_test_support.h"

#include <cstdio>

using namespace capi_test;

namespace {

constexpr uint32_t kPoints = 20;
constexpr double kEnd = 0.1;  // s

// The hinged bowel of test_convergence.cpp: 1 m, stretch, bend, gravity, first end pinned.
ent_scene_desc hinged_bowel(int32_t integrator) {
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) | ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.control_points = kPoints;
    desc.length_m = 1.0;
    desc.shape = ENT_SHAPE_LINE;
    desc.pinned_ends = ENT_PIN_FIRST;
    desc.integrator = integrator;
    return desc;
}

// The hinged bowel, stepped to kEnd with steps alternating between 1.25 h and 0.75 h (one
// substep each).
std::vector<double> run_alternating(int32_t integrator, double h) {
    ent_scene_desc desc = hinged_bowel(integrator);
    desc.timestep_s = 0.1;  // never subdivides: each step is one substep of its own dt
    desc.max_substeps = 1000000;
    ScenePtr scene = create(desc);
    if (!scene) return {};
    const long pairs = std::lround(kEnd / (2.0 * h));
    for (long k = 0; k < pairs; ++k) {
        for (const double dt : {1.25 * h, 0.75 * h}) {
            if (ent_scene_step(scene.get(), dt) != ENT_OK) {
                ADD_FAILURE() << "h " << h << ": " << ent_last_error();
                return {};
            }
        }
    }
    const ent_stats s = stats(scene.get());
    EXPECT_EQ(s.substeps, s.steps);
    return control_points(scene.get());
}

double max_point_distance(const std::vector<double>& a, const std::vector<double>& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i + 2 < a.size(); i += 3)
        worst = std::max(worst, std::hypot(a[i] - b[i], a[i + 1] - b[i + 1], a[i + 2] - b[i + 2]));
    return worst;
}

TEST(Bdf2, SecondOrderWhenTheStepChangesEveryStep) {
    // Reference: rk4 at a constant h/64 (its error is ~1e-13 m here, test_convergence.cpp).
    ent_scene_desc desc = default_desc();
    const double h = 1e-3;  // kEnd is a whole number of step pairs at h, h/2, h/4
    const std::vector<double> reference = [&] {
        desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                       ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) | ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
        desc.control_points = kPoints;
        desc.length_m = 1.0;
        desc.shape = ENT_SHAPE_LINE;
        desc.pinned_ends = ENT_PIN_FIRST;
        desc.integrator = ENT_INTEGRATOR_RK4;
        desc.timestep_s = h / 64;
        desc.max_substeps = 1000000;
        ScenePtr scene = create(desc);
        EXPECT_TRUE(step_n(scene.get(), h / 64, 64 * std::lround(kEnd / h)));
        return control_points(scene.get());
    }();
    double errors[3];
    for (int k = 0; k < 3; ++k) {
        const std::vector<double> q = run_alternating(ENT_INTEGRATOR_BDF2, h / double(1 << k));
        ASSERT_EQ(q.size(), reference.size());
        errors[k] = max_point_distance(q, reference);
    }
    const double order1 = std::log2(errors[0] / errors[1]), order2 = std::log2(errors[1] / errors[2]);
    std::printf("bdf2, alternating steps: e %.3e %.3e %.3e, orders %.3f %.3f\n", errors[0], errors[1], errors[2],
                order1, order2);
    // Constant-step coefficients on a varying step would fall to first order.
    EXPECT_GT(order1, 1.8);
    EXPECT_GT(order2, 1.8);
    EXPECT_LT(order1, 2.2);
    EXPECT_LT(order2, 2.2);
}

}  // namespace

// A point pinned while the bowel swings stays exactly where it was pinned: the pin stops it,
// and the method starts again from there (Integrator::restart), instead of extrapolating
// the point's motion before the pin (q_{n+1} = q_n + a (q_n - q_{n-1}) for a point whose
// velocity is held at zero).
TEST(Bdf2, APointPinnedBetweenStepsStaysWhereItWasPinned) {
    const ent_scene_desc desc = hinged_bowel(ENT_INTEGRATOR_BDF2);
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    for (int k = 0; k < 50; ++k) ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << ent_last_error();
    const uint32_t point = kPoints - 1;  // the free end, falling
    ASSERT_EQ(ent_scene_pin_point(scene.get(), point, ENT_NO_OBSTACLE), ENT_OK) << ent_last_error();
    const std::vector<double> pinned = control_points(scene.get());
    for (int k = 0; k < 20; ++k) {
        ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << ent_last_error();
        const std::vector<double> now = control_points(scene.get());
        for (int c = 0; c < 3; ++c) EXPECT_EQ(now[3 * point + c], pinned[3 * point + c]) << "step " << k << " coordinate " << c;
    }
}
