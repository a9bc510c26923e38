// SPDX-License-Identifier: Apache-2.0
// Gravity (lib/mechanics/gravity_force.h): minus the gradient of its energy, summing to the
// weight of the bowel.
#include "mechanics/gravity_force.h"

#include <gtest/gtest.h>

#include <memory_resource>

#include "mechanics/axis_model.h"
#include "mechanics/effect_checks.h"
#include "mechanics/state.h"

namespace {

using namespace mechanics_test;

TEST(GravityForce, ForceIsMinusTheGradientAndSumsToTheWeight) {
    const enteron::Vec3 g(0.5, -1.0, -9.81);
    mech::GravityForce gravity(model(), g, std::pmr::get_default_resource());
    const mech::State s = stretched_state(35);
    expect_force_is_minus_gradient(gravity, s, 1e-8);
    const auto f = force_of(gravity, s);
    for (int c = 0; c < 3; ++c) {
        double total = 0.0;
        for (std::size_t i = 0; i < kPoints; ++i) total += f[3 * i + c];
        EXPECT_NEAR(total, kDensity * kLength * g[c], 1e-12) << "coordinate " << c;
    }
}

}  // namespace
