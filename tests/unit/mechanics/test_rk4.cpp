// SPDX-License-Identifier: Apache-2.0
// The classic Runge-Kutta method (lib/mechanics/rk4.h) on the axis as harmonic oscillators
// (oscillator.h): each substep is the method's amplification matrix, the Taylor polynomial
// of exp(h A) to fourth order with A = [0 1; -omega^2 0], to round-off; its stability
// interval (2.7) lies inside the region where the oscillation stays bounded (2.83) and a
// substep beyond it grows. Its order against the closed form: test_integrator.cpp.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "mechanics/oscillator.h"
#include "mechanics/rk4.h"

namespace enteron::mechanics {
namespace {

using mechanics_test::Oscillator;

RungeKutta4 make_method() {
    return RungeKutta4(3 * mechanics_test::kOscillatorPoints, std::pmr::new_delete_resource());
}

// The RK4 amplification matrix of y' = A y over h: I + hA + (hA)^2/2 + (hA)^3/6 + (hA)^4/24.
Eigen::Matrix2d amplification(double h, double omega) {
    Eigen::Matrix2d a;
    a << 0.0, 1.0, -omega * omega, 0.0;
    const Eigen::Matrix2d ha = h * a;
    Eigen::Matrix2d term = Eigen::Matrix2d::Identity(), sum = Eigen::Matrix2d::Identity();
    for (int k = 1; k <= 4; ++k) {
        term = term * ha / double(k);
        sum += term;
    }
    return sum;
}

TEST(RungeKutta4, EachSubstepIsTheFourthOrderTaylorMap) {
    for (const double h_omega : {0.05, 1.0, 2.5}) {
        Oscillator o(10.0);
        RungeKutta4 method = make_method();
        const double h = h_omega / o.omega;
        const Eigen::Matrix2d r = amplification(h, o.omega);
        State expected = o.state;
        for (int step = 0; step < 40; ++step) {
            ASSERT_TRUE(method.step(o.dynamics, o.state, h));
            for (std::size_t k = 0; k < expected.q.size(); ++k) {
                const Eigen::Vector2d y = r * Eigen::Vector2d(expected.q[k], expected.v[k]);
                expected.q[k] = y[0];
                expected.v[k] = y[1];
                ASSERT_NEAR(o.state.q[k], y[0], 1e-12) << "h omega " << h_omega << ", step " << step;
                ASSERT_NEAR(o.state.v[k], y[1], 1e-11) << "h omega " << h_omega << ", step " << step;
            }
        }
        EXPECT_NEAR(o.state.time, 40 * h, 1e-12);
    }
}

TEST(RungeKutta4, StableWithinItsIntervalAndGrowingBeyondTheRegion) {
    RungeKutta4 method = make_method();
    EXPECT_EQ(method.stability_interval(), 2.7);
    // |R(i y)| of the oscillation's eigenvalues: below 1 up to 2 sqrt(2) = 2.83.
    for (const double h_omega : {2.7, 3.0}) {
        const double growth = std::abs(amplification(h_omega, 1.0).eigenvalues()[0]);
        Oscillator o(10.0);
        const double start = o.energy();
        ASSERT_TRUE(o.run(method, h_omega / o.omega, 400));
        if (h_omega <= method.stability_interval()) {
            EXPECT_LT(growth, 1.0);
            EXPECT_LE(o.energy(), start) << "damped, never growing, at h omega " << h_omega;
        } else {
            EXPECT_GT(growth, 1.0);
            EXPECT_GT(o.energy(), 1e3 * start) << "growing at h omega " << h_omega;
        }
    }
}

}  // namespace
}  // namespace enteron::mechanics
