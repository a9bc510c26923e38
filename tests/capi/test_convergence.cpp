// SPDX-License-Identifier: Apache-2.0
// Observed order of accuracy of each integrator on a smooth problem: a 1 m bowel, straight and
// horizontal, hinged at its first control point, released under gravity with stretch and bend
// (no damping), 20 control points, t_end = 0.1 s. Each run uses timestep_s = dt and steps by dt,
// for dt = h, h/2, h/4; the error is the largest control point distance at t_end from a
// reference run of rk4 at h/64 (whose own error is ~64^4 times below rk4's at h). The
// observed order is log2(e(dt) / e(dt/2)).
//
// h is chosen below the library's explicit stability limit for this scene, so that the
// explicit integrators are not subdivided (checked through ent_stats.substeps): otherwise
// they would run at a smaller substep than dt and the ratios would not measure the order.
// The library's limits here, read from ent_stats.substeps of a 10 ms step: rk4 1.43 ms,
// symplectic Euler 1.11 ms. h = 0.8 ms.
//
// Measured (h = 0.8 ms):
//   rk4               e = 6.20e-9, 4.20e-10, 2.72e-11 m   orders 3.884, 3.948
//   symplectic Euler  e = 4.48e-4, 2.24e-4, 1.12e-4 m     orders 1.000, 1.000
//   implicit Euler    e = 5.22e-4, 2.62e-4, 1.32e-4 m     orders 0.993, 0.994
// The rk4 errors stay three decades above round-off (the reference agrees with itself at
// h/128 to ~3e-14 m). The bounds: the asymptotic orders 4 and 1, with room for the
// pre-asymptotic drift seen above (rk4 3.7 to 4.3, Euler 0.9 to 1.1).
#include "capi_test_support.h"

#include <cstdio>
#include <ostream>

using namespace capi_test;

namespace {

constexpr uint32_t kConvergencePoints = 20;
constexpr double kConvergenceEnd = 0.1;

struct RunResult {
    std::vector<double> q;
    uint64_t steps = 0;
    uint64_t substeps = 0;
};

RunResult convergence_run(int32_t integrator, double dt) {
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) | ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.control_points = kConvergencePoints;
    desc.length_m = 1.0;
    desc.shape = ENT_SHAPE_LINE;
    desc.pinned_ends = ENT_PIN_FIRST;
    desc.integrator = integrator;
    desc.timestep_s = dt;
    desc.max_substeps = 1000000;
    ScenePtr scene = create(desc);
    RunResult out;
    if (!scene) return out;
    const long steps = std::lround(kConvergenceEnd / dt);
    for (long k = 0; k < steps; ++k) {
        if (ent_scene_step(scene.get(), dt) != ENT_OK) {
            ADD_FAILURE() << integrator_name(integrator) << " dt " << dt << " step " << k << ": " << ent_last_error();
            return out;
        }
    }
    const ent_stats s = stats(scene.get());
    EXPECT_NEAR(s.time_s, kConvergenceEnd, 1e-12);
    out.q = control_points(scene.get());
    out.steps = s.steps;
    out.substeps = s.substeps;
    return out;
}

double convergence_max_point_distance(const std::vector<double>& a, const std::vector<double>& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i + 2 < a.size(); i += 3) {
        const double dx = a[i] - b[i], dy = a[i + 1] - b[i + 1], dz = a[i + 2] - b[i + 2];
        worst = std::max(worst, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    return worst;
}

struct Expectation {
    int32_t integrator;
    double min_order;
    double max_order;
};

// Names the parameter in test listings instead of dumping its bytes.
void PrintTo(const Expectation& e, std::ostream* os) {
    *os << integrator_name(e.integrator) << ", order in [" << e.min_order << ", " << e.max_order << "]";
}

class Convergence : public ::testing::TestWithParam<Expectation> {};

constexpr double kBaseStep = 0.8e-3;  // s, below both explicit limits (see above)

TEST_P(Convergence, ObservedOrderAtTheEndTime) {
    const Expectation expectation = GetParam();
    const double h = kBaseStep;
    static const RunResult reference = convergence_run(ENT_INTEGRATOR_RK4, h / 64);
    ASSERT_EQ(reference.q.size(), 3u * kConvergencePoints);

    double errors[3];
    for (int k = 0; k < 3; ++k) {
        const double dt = h / double(1 << k);
        const RunResult r = convergence_run(expectation.integrator, dt);
        ASSERT_EQ(r.q.size(), 3u * kConvergencePoints);
        EXPECT_EQ(r.substeps, r.steps) << "dt " << dt << " was subdivided: lower h";
        errors[k] = convergence_max_point_distance(r.q, reference.q);
    }
    const double order1 = std::log2(errors[0] / errors[1]);
    const double order2 = std::log2(errors[1] / errors[2]);
    std::printf("%s: e(h) %.3e, e(h/2) %.3e, e(h/4) %.3e, orders %.3f %.3f\n",
                integrator_name(expectation.integrator), errors[0], errors[1], errors[2], order1, order2);
    EXPECT_GE(order1, expectation.min_order);
    EXPECT_LE(order1, expectation.max_order);
    EXPECT_GE(order2, expectation.min_order);
    EXPECT_LE(order2, expectation.max_order);
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, Convergence,
                         ::testing::Values(Expectation{ENT_INTEGRATOR_RK4, 3.7, 4.3},
                                           Expectation{ENT_INTEGRATOR_SYMPLECTIC_EULER, 0.9, 1.1},
                                           Expectation{ENT_INTEGRATOR_IMPLICIT_EULER, 0.9, 1.1},
                                           Expectation{ENT_INTEGRATOR_BDF2, 1.8, 2.2}),
                         [](const ::testing::TestParamInfo<Expectation>& info) {
                             return std::string(integrator_name(info.param.integrator));
                         });

}  // namespace
