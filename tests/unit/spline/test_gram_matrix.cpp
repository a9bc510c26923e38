// SPDX-License-Identifier: Apache-2.0
// Gram matrices of the spline basis (lib/spline/gram_matrix.h), checked against integrals
// computed here with Simpson's rule over the formula of docs/architecture.md.
#include "spline/gram_matrix.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "spline/spline_reference.h"

namespace {

namespace sp = enteron::spline;
using sp::Derivative;
using enteron_test::random_vector;
using enteron_test::ReferenceSpline;
using enteron_test::simpson01;

enteron::numerics::ScalarBandMatrix gram(std::size_t n, Derivative order, double scale) {
    enteron::numerics::ScalarBandMatrix m;
    m.resize(n);
    sp::add_gram_matrix(n, order, scale, m);
    return m;
}

double quadratic_form(const enteron::numerics::ScalarBandMatrix& m, const std::vector<double>& x) {
    std::vector<double> y(x.size());
    m.multiply(x.data(), y.data());
    double s = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) s += x[i] * y[i];
    return s;
}

// scale * sum over segments of the integral over t of (d^order/dt^order of the scalar spline
// through x)^2, per segment so that the jumps of P'' at the joints do not matter.
double reference_integral(const std::vector<double>& x, int order, double scale) {
    const ReferenceSpline ref(x, 1);
    double total = 0.0;
    for (std::size_t seg = 0; seg + 1 < ref.count(); ++seg)
        total += simpson01([&](double t) {
            const double p = ref.at(seg, t, order, 0);
            return p * p;
        });
    return scale * total;
}

TEST(GramMatrix, KineticEnergyMatchesTheIntegralOfMuTimesSpeedSquared) {
    // v^T M v = integral of mu |dP/dt|^2 ds with ds = l0 dparam, M = gram(value, mu l0).
    std::mt19937_64 rng(11);
    const double mu = 0.3;
    for (std::size_t n : {std::size_t(4), std::size_t(5), std::size_t(13), std::size_t(40)}) {
        const double length = 2.0;
        const double l0 = length / double(n - 1);
        const auto m = gram(n, Derivative::value, mu * l0);
        for (int trial = 0; trial < 5; ++trial) {
            // One random velocity per coordinate: the three coordinates share M.
            double form = 0.0, integral = 0.0;
            for (int c = 0; c < 3; ++c) {
                const auto v = random_vector(n, rng);
                form += quadratic_form(m, v);
                integral += reference_integral(v, 0, mu * l0);
            }
            EXPECT_NEAR(form, integral, 1e-10 * integral) << "n " << n;
        }
    }
}

TEST(GramMatrix, FirstAndSecondDerivativeGramsMatchTheirIntegrals) {
    std::mt19937_64 rng(12);
    for (std::size_t n : {std::size_t(4), std::size_t(6), std::size_t(21)}) {
        for (int order : {1, 2}) {
            const double scale = 0.7 + order;
            const auto g = gram(n, Derivative(order), scale);
            for (int trial = 0; trial < 5; ++trial) {
                const auto x = random_vector(n, rng);
                const double expected = reference_integral(x, order, scale);
                EXPECT_NEAR(quadratic_form(g, x), expected, 1e-10 * expected)
                    << "n " << n << " order " << order;
            }
        }
    }
}

TEST(GramMatrix, EntriesOfTheMassMatrixSumToTheTotalMass) {
    // 1^T M 1 = integral of mu (sum_j w_j)^2 ds = mu L: a rigid translation at unit speed.
    const double mu = 0.3, length = 6.0;
    for (std::size_t n : {std::size_t(4), std::size_t(10), std::size_t(240)}) {
        const auto m = gram(n, Derivative::value, mu * length / double(n - 1));
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) sum += m.at(i, j);
        EXPECT_NEAR(sum, mu * length, 1e-12 * mu * length) << "n " << n;
    }
}

TEST(GramMatrix, MassMatrixIsSymmetricPositiveDefinite) {
    std::mt19937_64 rng(13);
    for (std::size_t n : {std::size_t(4), std::size_t(7), std::size_t(100)}) {
        auto m = gram(n, Derivative::value, 0.3 * 0.025);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                EXPECT_EQ(m.at(i, j), m.at(j, i));
                if (i > j + 3) {
                    EXPECT_EQ(m.at(i, j), 0.0);
                }
            }
        for (int trial = 0; trial < 10; ++trial) EXPECT_GT(quadratic_form(m, random_vector(n, rng)), 0.0);
        // The factorisation solves M x = b.
        const auto b = random_vector(n, rng);
        const enteron::numerics::ScalarBandMatrix original = m;
        ASSERT_TRUE(m.factor()) << "n " << n;
        auto x = b;
        m.solve(x.data());
        std::vector<double> back(n);
        original.multiply(x.data(), back.data());
        for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(back[i], b[i], 1e-10);
    }
}

TEST(GramMatrix, BendingGramVanishesOnAStraightEvenlySpacedLine) {
    // A straight bowel at rest stores no bending energy: K_b q = 0 per coordinate.
    const std::size_t n = 15;
    const auto k = gram(n, Derivative::second, 1.0);
    std::vector<double> q(n), out(n);
    for (std::size_t i = 0; i < n; ++i) q[i] = 0.4 - 0.05 * double(i);
    k.multiply(q.data(), out.data());
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(out[i], 0.0, 1e-12) << i;
    // ... but not on a bent one.
    for (std::size_t i = 0; i < n; ++i) q[i] = 0.01 * double(i * i);
    EXPECT_GT(quadratic_form(k, q), 1e-6);
}

TEST(GramMatrix, AddsToTheExistingEntries) {
    const std::size_t n = 8;
    auto twice = gram(n, Derivative::value, 1.0);
    sp::add_gram_matrix(n, Derivative::value, 1.0, twice);
    const auto once = gram(n, Derivative::value, 2.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) EXPECT_NEAR(twice.at(i, j), once.at(i, j), 1e-15);
}

}  // namespace
