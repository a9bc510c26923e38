// SPDX-License-Identifier: Apache-2.0
// Shared by the tests of lib/mechanics: a small axis and a stretched state of it, and
// checks of an effect against its energy and against finite differences. Every conservative
// force must be minus the gradient of its potential energy, and the linearisation handed to
// the implicit integrator (H = -dF/dq, C = -dF/dv, H v) must be the derivative of the force
// it linearises: a wrong sign or a missing term makes the implicit integrator converge
// slowly or gain energy, which the C API tests would only show indirectly.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/effect.h"
#include "mechanics/state.h"
#include "mechanics/system_matrix.h"

namespace mechanics_test {

namespace mech = enteron::mechanics;

constexpr std::size_t kPoints = 10;
constexpr double kLength = 1.0;
constexpr double kDensity = 0.3;

inline mech::AxisModel model() {
    mech::AxisModel m;
    m.control_points = kPoints;
    m.rest_segment_length = kLength / double(kPoints - 1);
    m.linear_density = kDensity;
    return m;
}

// A bent axis stretched by about 10 % everywhere (so no stretch node is compressed and the
// stretch Hessian needs no clamping), with random velocities.
inline mech::State stretched_state(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    mech::State s;
    s.resize(kPoints);
    const double l0 = model().rest_segment_length;
    for (std::size_t i = 0; i < kPoints; ++i) {
        s.q[3 * i + 0] = 1.1 * l0 * double(i);
        s.q[3 * i + 1] = 0.02 * std::sin(double(i)) + 0.002 * u(rng);
        s.q[3 * i + 2] = 0.01 * std::cos(2.0 * double(i)) + 0.002 * u(rng);
    }
    for (double& v : s.v) v = 0.3 * u(rng);
    return s;
}

inline std::vector<double> force_of(mech::Effect& effect, const mech::State& state) {
    std::vector<double> f(3 * kPoints, 0.0);
    effect.evaluate(state, f.data(), nullptr);
    return f;
}

inline double max_abs(const std::vector<double>& x) {
    double m = 0.0;
    for (double v : x) m = std::max(m, std::fabs(v));
    return m;
}

// F_k versus -dE/dq_k by central differences.
inline void expect_force_is_minus_gradient(mech::Effect& effect, const mech::State& state, double rel_tol) {
    const auto f = force_of(effect, state);
    const double scale = max_abs(f);
    ASSERT_GT(scale, 0.0) << "the state must load this effect";
    const double delta = 1e-6;
    for (std::size_t k = 0; k < f.size(); ++k) {
        mech::State plus = state, minus = state;
        plus.q[k] += delta;
        minus.q[k] -= delta;
        const double gradient = (effect.potential_energy(plus) - effect.potential_energy(minus)) / (2 * delta);
        EXPECT_NEAR(f[k], -gradient, rel_tol * scale) << "coordinate " << k;
    }
}

// The full 3n x 3n matrix -dF/dx by central differences, x = q or v.
inline std::vector<std::vector<double>> minus_jacobian(mech::Effect& effect, const mech::State& state, bool of_velocity) {
    const std::size_t m = 3 * kPoints;
    std::vector<std::vector<double>> j(m, std::vector<double>(m, 0.0));
    const double delta = 1e-6;
    for (std::size_t col = 0; col < m; ++col) {
        mech::State plus = state, minus = state;
        (of_velocity ? plus.v : plus.q)[col] += delta;
        (of_velocity ? minus.v : minus.q)[col] -= delta;
        const auto fp = force_of(effect, plus);
        const auto fm = force_of(effect, minus);
        for (std::size_t row = 0; row < m; ++row) j[row][col] = -(fp[row] - fm[row]) / (2 * delta);
    }
    return j;
}

inline void expect_matrix_matches(const mech::SystemMatrix& system, const std::vector<std::vector<double>>& expected,
                           double rel_tol) {
    double scale = 0.0;
    for (const auto& row : expected)
        for (double v : row) scale = std::max(scale, std::fabs(v));
    ASSERT_GT(scale, 0.0);
    for (std::size_t i = 0; i < expected.size(); ++i)
        for (std::size_t j = 0; j < expected.size(); ++j)
            EXPECT_NEAR(system.at(i, j), expected[i][j], rel_tol * scale) << "(" << i << ", " << j << ")";
}

struct Linearized {
    mech::SystemMatrix system;
    std::vector<double> force;
    std::vector<double> stiffness_times_velocity;
};

// Runs evaluate with a linearisation at h = 1 (so the system holds C + H) on top of the
// constant part, from a zero system.
inline Linearized linearize(mech::Effect& effect, const mech::State& state) {
    Linearized out;
    out.system.resize(3 * kPoints);
    out.force.assign(3 * kPoints, 0.0);
    out.stiffness_times_velocity.assign(3 * kPoints, 0.0);
    effect.add_constant_linearization(1.0, out.system);
    mech::Linearization lin{&out.system, 1.0, out.stiffness_times_velocity.data()};
    effect.evaluate(state, out.force.data(), &lin);
    return out;
}

inline std::vector<double> times(const std::vector<std::vector<double>>& a, const std::vector<double>& x) {
    std::vector<double> y(x.size(), 0.0);
    for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = 0; j < x.size(); ++j) y[i] += a[i][j] * x[j];
    return y;
}

}  // namespace mechanics_test
