// SPDX-License-Identifier: Apache-2.0
// Damping (lib/mechanics/damping_force.h): a linearisation that is its velocity Jacobian,
// it only dissipates, and a rigid translation feels only the drag.
#include "mechanics/damping_force.h"

#include <gtest/gtest.h>

#include <memory_resource>
#include <random>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/effect_checks.h"
#include "mechanics/state.h"

namespace {

using namespace mechanics_test;

TEST(DampingForce, LinearizationIsTheVelocityJacobianAndItDissipates) {
    const mech::DampingCoefficients coefficients{0.05, 0.05, 1e-3};
    mech::DampingForce damping(model(), coefficients, std::pmr::get_default_resource());
    const mech::State s = stretched_state(36);
    const Linearized lin = linearize(damping, s);
    expect_matrix_matches(lin.system, minus_jacobian(damping, s, true), 1e-6);

    // Power of the damping force is never positive.
    std::mt19937_64 rng(37);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        mech::State moving = s;
        for (double& v : moving.v) v = u(rng);
        const auto f = force_of(damping, moving);
        double power = 0.0;
        for (std::size_t k = 0; k < f.size(); ++k) power += f[k] * moving.v[k];
        EXPECT_LT(power, 0.0);
    }
}

TEST(DampingForce, RigidTranslationFeelsOnlyDrag) {
    // Strain rate and curvature rate are zero, so only the drag acts: total -c_d L v.
    const mech::DampingCoefficients coefficients{0.05, 10.0, 10.0};
    mech::DampingForce damping(model(), coefficients, std::pmr::get_default_resource());
    mech::State s = stretched_state(38);
    const double v[3] = {0.3, -0.2, 0.1};
    for (std::size_t i = 0; i < kPoints; ++i)
        for (int c = 0; c < 3; ++c) s.v[3 * i + c] = v[c];
    const auto f = force_of(damping, s);
    for (int c = 0; c < 3; ++c) {
        double total = 0.0;
        for (std::size_t i = 0; i < kPoints; ++i) total += f[3 * i + c];
        // Had the stretch or bend damping (10 N s, 10 N m^2 s) acted on this motion, the sum
        // would be off by newtons; round-off of the bend damping matrix (entries ~ c_b / l0^3
        // = 7e3) times a constant vector leaves ~1e-10.
        EXPECT_NEAR(total, -coefficients.drag * kLength * v[c], 1e-9) << "coordinate " << c;
    }
}

}  // namespace
