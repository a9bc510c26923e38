// SPDX-License-Identifier: Apache-2.0
// The mesentery (lib/mechanics/mesentery_force.h): tension-only springs, minus the gradient
// of their energy with a linearisation that is their Jacobian; slack springs pull nothing.
#include "mechanics/mesentery_force.h"

#include <gtest/gtest.h>

#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/effect_checks.h"
#include "mechanics/state.h"

namespace {

using namespace mechanics_test;

TEST(MesenteryForce, ForceIsMinusTheGradientAndTheLinearizationItsJacobian) {
    mech::MesenteryParameters p;
    p.root_start = {-0.075, -0.3, 0.0};
    p.root_end = {0.075, -0.3, 0.0};
    p.attachments = 7;
    p.stiffness = 5.0;
    p.rest_length = 0.05;  // shorter than every spring: all pull
    const mech::State s = stretched_state(39);
    mech::MesenteryForce mesentery(model(), p, s, std::pmr::get_default_resource());
    expect_force_is_minus_gradient(mesentery, s, 1e-6);
    const Linearized lin = linearize(mesentery, s);
    const auto h = minus_jacobian(mesentery, s, false);
    expect_matrix_matches(lin.system, h, 1e-6);
    const auto hv = times(h, std::vector<double>(s.v.begin(), s.v.end()));
    for (std::size_t k = 0; k < hv.size(); ++k)
        EXPECT_NEAR(lin.stiffness_times_velocity[k], hv[k], 1e-6 * max_abs(hv)) << k;
}

TEST(MesenteryForce, SlackSpringsPullNothing) {
    mech::MesenteryParameters p;
    p.root_start = {-0.075, -0.3, 0.0};
    p.root_end = {0.075, -0.3, 0.0};
    p.attachments = 7;
    p.stiffness = 5.0;
    p.rest_length = 0.0;  // each spring's initial length
    const mech::State s = stretched_state(40);
    mech::MesenteryForce mesentery(model(), p, s, std::pmr::get_default_resource());
    EXPECT_EQ(max_abs(force_of(mesentery, s)), 0.0);
    EXPECT_EQ(mesentery.potential_energy(s), 0.0);
    // Moving every point toward the root slackens every spring further.
    mech::State closer = s;
    for (std::size_t i = 0; i < kPoints; ++i) closer.q[3 * i + 1] -= 0.05;
    EXPECT_EQ(max_abs(force_of(mesentery, closer)), 0.0);
}

}  // namespace
