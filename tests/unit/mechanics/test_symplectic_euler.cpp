// SPDX-License-Identifier: Apache-2.0
// Symplectic Euler (lib/mechanics/symplectic_euler.h) on the axis as harmonic oscillators
// (oscillator.h): each substep is v1 = v0 - h omega^2 q0, q1 = q0 + h v1 to round-off; the
// energy stays within O(h omega) of its start over many periods without drifting (the
// method conserves a nearby shadow energy); beyond h omega = 2 it grows without bound, as
// its stability interval (2) says. Its order against the closed form: test_integrator.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mechanics/oscillator.h"
#include "mechanics/symplectic_euler.h"

namespace enteron::mechanics {
namespace {

using mechanics_test::Oscillator;

SymplecticEuler symplectic_euler_make_method() {
    return SymplecticEuler(3 * mechanics_test::kOscillatorPoints, std::pmr::new_delete_resource());
}

TEST(SymplecticEuler, EachSubstepIsTheSymplecticEulerMap) {
    Oscillator o(10.0);
    SymplecticEuler method = symplectic_euler_make_method();
    const double h = 0.01, w2 = o.omega * o.omega;
    State expected = o.state;
    for (int step = 0; step < 50; ++step) {
        ASSERT_TRUE(method.step(o.dynamics, o.state, h));
        for (std::size_t k = 0; k < expected.q.size(); ++k) {
            expected.v[k] -= h * w2 * expected.q[k];
            expected.q[k] += h * expected.v[k];
            ASSERT_NEAR(o.state.q[k], expected.q[k], 1e-13) << "step " << step;
            ASSERT_NEAR(o.state.v[k], expected.v[k], 1e-12) << "step " << step;
        }
    }
}

TEST(SymplecticEuler, TheEnergyStaysNearItsStartWithoutDrifting) {
    Oscillator o(2.0 * kPi);  // a period of 1 s
    SymplecticEuler method = symplectic_euler_make_method();
    const double h = 0.01;  // h omega = 0.063
    const double start = o.energy();
    const auto deviation_over_a_period = [&] {
        double largest = 0.0;
        for (int step = 0; step < 100; ++step) {
            EXPECT_TRUE(method.step(o.dynamics, o.state, h));
            largest = std::max(largest, std::fabs(o.energy() - start) / start);
        }
        return largest;
    };
    const double first = deviation_over_a_period();
    for (int period = 1; period < 999; ++period) deviation_over_a_period();
    const double thousandth = deviation_over_a_period();
    EXPECT_LT(first, 2.0 * h * o.omega);
    EXPECT_LT(thousandth, 1.05 * first) << "no drift over 1000 periods";
}

TEST(SymplecticEuler, BeyondItsStabilityIntervalItGrows) {
    SymplecticEuler method = symplectic_euler_make_method();
    EXPECT_EQ(method.stability_interval(), 2.0);
    for (const double h_omega : {1.9, 2.1}) {
        Oscillator o(10.0);
        const double start = o.energy();
        ASSERT_TRUE(o.run(method, h_omega / o.omega, 300));
        if (h_omega < 2.0) EXPECT_LT(o.energy(), 100.0 * start) << "bounded at h omega " << h_omega;
        else EXPECT_GT(o.energy(), 1e6 * start) << "unbounded at h omega " << h_omega;
    }
}

}  // namespace
}  // namespace enteron::mechanics
