// SPDX-License-Identifier: Apache-2.0
// The bend effect (lib/mechanics/bend_force.h): minus the gradient of its energy, and a
// linearisation that is its Jacobian.
#include "mechanics/bend_force.h"

#include <gtest/gtest.h>

#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/effect_checks.h"
#include "mechanics/state.h"

namespace {

using namespace mechanics_test;

TEST(BendForce, ForceIsMinusTheGradientOfItsEnergy) {
    mech::BendForce bend(model(), 2.5e-3, std::pmr::get_default_resource());
    expect_force_is_minus_gradient(bend, stretched_state(33), 1e-6);
}

TEST(BendForce, LinearizationIsTheJacobian) {
    mech::BendForce bend(model(), 2.5e-3, std::pmr::get_default_resource());
    const mech::State s = stretched_state(34);
    const Linearized lin = linearize(bend, s);
    const auto k = minus_jacobian(bend, s, false);
    expect_matrix_matches(lin.system, k, 1e-6);
    const auto kv = times(k, std::vector<double>(s.v.begin(), s.v.end()));
    for (std::size_t i = 0; i < kv.size(); ++i)
        EXPECT_NEAR(lin.stiffness_times_velocity[i], kv[i], 1e-6 * max_abs(kv)) << i;
}

}  // namespace
