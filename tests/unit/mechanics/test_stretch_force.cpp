// SPDX-License-Identifier: Apache-2.0
// The stretch effect (lib/mechanics/stretch_force.h): minus the gradient of its energy, zero
// at rest, the energy of a uniform stretch, and a linearisation that is its Jacobian.
#include "mechanics/stretch_force.h"

#include <gtest/gtest.h>

#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/effect_checks.h"
#include "mechanics/state.h"

namespace {

using namespace mechanics_test;

TEST(StretchForce, ForceIsMinusTheGradientOfItsEnergy) {
    mech::StretchForce stretch(model(), 100.0, std::pmr::get_default_resource());
    expect_force_is_minus_gradient(stretch, stretched_state(31), 1e-6);
}

TEST(StretchForce, ZeroOnTheStraightLineAtRestLength) {
    mech::StretchForce stretch(model(), 100.0, std::pmr::get_default_resource());
    mech::State s;
    s.resize(kPoints);
    for (std::size_t i = 0; i < kPoints; ++i) s.q[3 * i] = model().rest_segment_length * double(i);
    EXPECT_LT(max_abs(force_of(stretch, s)), 1e-12);
    EXPECT_LT(stretch.potential_energy(s), 1e-24);
}

TEST(StretchForce, EnergyOfAUniformStretch) {
    // Straight, every segment stretched by 5 %: E = 1/2 EA eps^2 L.
    const double ea = 100.0, eps = 0.05;
    mech::StretchForce stretch(model(), ea, std::pmr::get_default_resource());
    mech::State s;
    s.resize(kPoints);
    for (std::size_t i = 0; i < kPoints; ++i) s.q[3 * i] = (1 + eps) * model().rest_segment_length * double(i);
    EXPECT_NEAR(stretch.potential_energy(s), 0.5 * ea * eps * eps * kLength, 1e-12);
}

TEST(StretchForce, LinearizationIsTheJacobianWhenStretched) {
    mech::StretchForce stretch(model(), 100.0, std::pmr::get_default_resource());
    const mech::State s = stretched_state(32);
    const Linearized lin = linearize(stretch, s);
    const auto h = minus_jacobian(stretch, s, false);
    expect_matrix_matches(lin.system, h, 1e-6);
    const auto hv = times(h, std::vector<double>(s.v.begin(), s.v.end()));
    for (std::size_t k = 0; k < hv.size(); ++k)
        EXPECT_NEAR(lin.stiffness_times_velocity[k], hv[k], 1e-6 * max_abs(hv)) << k;
    const auto plain = force_of(stretch, s);
    for (std::size_t k = 0; k < plain.size(); ++k) EXPECT_EQ(lin.force[k], plain[k]);
}

}  // namespace
