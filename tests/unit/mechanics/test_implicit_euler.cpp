// SPDX-License-Identifier: Apache-2.0
// The linearised implicit Euler substep (lib/mechanics/implicit_euler.h) on the axis as
// harmonic oscillators (oscillator.h): for a linear force the linearisation is exact, so
// each substep is the backward Euler map of the oscillator,
//   v1 = v0 - h omega^2 (q0 + h v0) / (1 + h^2 omega^2),   q1 = q0 + h v1,
// to round-off, at any h; it never gains energy (unconditionally stable, dissipative).
// Its order against the closed form: test_integrator.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "mechanics/implicit_euler.h"
#include "mechanics/oscillator.h"

namespace enteron::mechanics {
namespace {

using mechanics_test::Oscillator;

TEST(ImplicitEuler, EachSubstepIsTheBackwardEulerMapOfTheOscillator) {
    for (const double h_omega : {0.01, 0.5, 20.0}) {
        Oscillator o(10.0);
        const double h = h_omega / o.omega, w2 = o.omega * o.omega;
        ImplicitEuler method(mechanics_test::oscillator_model(), std::pmr::new_delete_resource());
        State expected = o.state;
        for (int step = 0; step < 30; ++step) {
            ASSERT_TRUE(method.step(o.dynamics, o.state, h));
            double largest = 0.0, off = 0.0;
            for (std::size_t k = 0; k < expected.q.size(); ++k) {
                const double v = expected.v[k] - h * w2 * (expected.q[k] + h * expected.v[k]) / (1.0 + h * h * w2);
                expected.q[k] += h * v;
                expected.v[k] = v;
                largest = std::max({largest, std::fabs(expected.q[k]), std::fabs(expected.v[k]) * h});
                off = std::max({off, std::fabs(o.state.q[k] - expected.q[k]), std::fabs(o.state.v[k] - expected.v[k]) * h});
            }
            ASSERT_LT(off, 1e-10 * largest) << "h omega " << h_omega << ", step " << step;
        }
        EXPECT_NEAR(o.state.time, 30 * h, 1e-15);
    }
}

TEST(ImplicitEuler, TheEnergyNeverGrowsAtAnySubstep) {
    for (const double h_omega : {0.05, 1.0, 100.0}) {
        Oscillator o(10.0);
        ImplicitEuler method(mechanics_test::oscillator_model(), std::pmr::new_delete_resource());
        double energy = o.energy();
        const double start = energy;
        for (int step = 0; step < 200; ++step) {
            ASSERT_TRUE(method.step(o.dynamics, o.state, h_omega / o.omega));
            const double now = o.energy();
            ASSERT_LE(now, energy * (1.0 + 1e-12)) << "h omega " << h_omega << ", step " << step;
            energy = now;
        }
        // Backward Euler damps each period by (1 + (h omega)^2)^(-1/2) per substep at least.
        EXPECT_LT(energy, start * std::pow(1.0 + h_omega * h_omega, -200.0) * 1.01 + 1e-300) << h_omega;
    }
}

TEST(ImplicitEuler, ItIsImplicitAndSaysSo) {
    ImplicitEuler method(mechanics_test::oscillator_model(), std::pmr::new_delete_resource());
    EXPECT_TRUE(std::isinf(method.stability_interval()));
}

}  // namespace
}  // namespace enteron::mechanics
