// SPDX-License-Identifier: Apache-2.0
// The Catmull-Rom basis of lib/spline: interpolation, C1 joints, partition of unity, the end
// treatment, and agreement with the formula of docs/architecture.md.
#include "spline/catmull_rom.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "spline/spline_reference.h"

namespace {

using enteron::spline::Derivative;
using enteron::spline::SegmentWeights;
namespace sp = enteron::spline;
using enteron_test::random_vector;

enteron::Vec3 eval(const std::vector<double>& q, const SegmentWeights& w) { return sp::evaluate(q.data(), w); }

double max_abs_diff(const enteron::Vec3& a, const enteron::Vec3& b) { return (a - b).cwiseAbs().maxCoeff(); }

const std::size_t kCounts[] = {4, 5, 6, 9, 31};

TEST(CatmullRom, InterpolatesControlPointsAtIntegerParameters) {
    std::mt19937_64 rng(1);
    for (std::size_t n : kCounts) {
        const auto q = random_vector(3 * n, rng);
        for (std::size_t i = 0; i < n; ++i) {
            const auto p = eval(q, sp::weights_at(n, double(i), Derivative::value));
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], q[3 * i + c], 1e-14) << "n " << n << " i " << i;
        }
    }
}

TEST(CatmullRom, ValueAndFirstDerivativeAreContinuousAtTheJoints) {
    std::mt19937_64 rng(2);
    for (std::size_t n : kCounts) {
        for (int trial = 0; trial < 20; ++trial) {
            const auto q = random_vector(3 * n, rng, -10.0, 10.0);
            for (std::size_t seg = 0; seg + 2 < n; ++seg) {
                for (Derivative order : {Derivative::value, Derivative::first}) {
                    const auto left = eval(q, sp::segment_weights(n, seg, 1.0, order));
                    const auto right = eval(q, sp::segment_weights(n, seg + 1, 0.0, order));
                    EXPECT_LT(max_abs_diff(left, right), 1e-12)
                        << "n " << n << " joint " << seg + 1 << " order " << int(order);
                }
            }
        }
    }
}

TEST(CatmullRom, SecondDerivativeJumpsAtJointsSoTheTestAboveCanTellOrdersApart) {
    // A Catmull-Rom spline is only C1: for random points the second derivative differs across
    // a joint. Guards against a continuity test that would pass for any weights.
    std::mt19937_64 rng(3);
    const std::size_t n = 9;
    const auto q = random_vector(3 * n, rng);
    double largest_jump = 0.0;
    for (std::size_t seg = 0; seg + 2 < n; ++seg) {
        const auto left = eval(q, sp::segment_weights(n, seg, 1.0, Derivative::second));
        const auto right = eval(q, sp::segment_weights(n, seg + 1, 0.0, Derivative::second));
        largest_jump = std::max(largest_jump, max_abs_diff(left, right));
    }
    EXPECT_GT(largest_jump, 1e-3);
}

TEST(CatmullRom, WeightsSumToOneForValueAndZeroForDerivatives) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t n : kCounts) {
        for (std::size_t seg = 0; seg + 1 < n; ++seg) {
            for (int k = 0; k < 25; ++k) {
                const double t = k < 2 ? double(k) : unit(rng);
                for (int order = 0; order < 3; ++order) {
                    const auto w = sp::segment_weights(n, seg, t, Derivative(order));
                    const double sum = w.w[0] + w.w[1] + w.w[2] + w.w[3];
                    EXPECT_NEAR(sum, order == 0 ? 1.0 : 0.0, 1e-13)
                        << "n " << n << " segment " << seg << " t " << t << " order " << order;
                    EXPECT_LE(w.first + 3, n - 1) << "window leaves the control points";
                }
            }
        }
    }
}

TEST(CatmullRom, StraightEvenlySpacedLineIsReproducedExactly) {
    // q_i = a + i d: with the linear phantom points P(s) = a + s d on every segment, so
    // P' = d and P'' = 0 everywhere, the end segments included.
    const std::size_t n = 12;
    const double a[3] = {0.3, -1.2, 2.0};
    const double d[3] = {0.05, 0.02, -0.01};
    std::vector<double> q(3 * n);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) q[3 * i + c] = a[c] + double(i) * d[c];
    for (int k = 0; k <= 1100; ++k) {
        const double s = (n - 1) * k / 1100.0;
        const auto p = eval(q, sp::weights_at(n, s, Derivative::value));
        const auto p1 = eval(q, sp::weights_at(n, s, Derivative::first));
        const auto p2 = eval(q, sp::weights_at(n, s, Derivative::second));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(p[c], a[c] + s * d[c], 1e-14) << "s " << s;
            EXPECT_NEAR(p1[c], d[c], 1e-14) << "s " << s;
            EXPECT_NEAR(p2[c], 0.0, 1e-14) << "s " << s;
        }
    }
}

TEST(CatmullRom, MatchesTheDesignFormulaWithPhantomPoints) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t n : kCounts) {
        const auto q = random_vector(3 * n, rng);
        const enteron_test::ReferenceSpline ref(q, 3);
        for (std::size_t seg = 0; seg + 1 < n; ++seg) {
            for (int k = 0; k < 10; ++k) {
                const double t = unit(rng);
                for (int order = 0; order < 3; ++order) {
                    const auto p = eval(q, sp::segment_weights(n, seg, t, Derivative(order)));
                    for (int c = 0; c < 3; ++c)
                        EXPECT_NEAR(p[c], ref.at(seg, t, order, c), 1e-13)
                            << "n " << n << " segment " << seg << " order " << order;
                }
            }
        }
    }
}

TEST(CatmullRom, DerivativeWeightsAreDerivativesOfTheValueWeights) {
    const double eps = 1e-6;
    for (std::size_t n : {std::size_t(4), std::size_t(7)}) {
        for (std::size_t seg = 0; seg + 1 < n; ++seg) {
            for (double t : {0.1, 0.37, 0.5, 0.9}) {
                for (int order = 1; order < 3; ++order) {
                    const auto lo = sp::segment_weights(n, seg, t - eps, Derivative(order - 1));
                    const auto hi = sp::segment_weights(n, seg, t + eps, Derivative(order - 1));
                    const auto w = sp::segment_weights(n, seg, t, Derivative(order));
                    ASSERT_EQ(lo.first, w.first);
                    for (int j = 0; j < 4; ++j)
                        EXPECT_NEAR(w.w[j], (hi.w[j] - lo.w[j]) / (2 * eps), 1e-7)
                            << "segment " << seg << " t " << t << " order " << order << " j " << j;
                }
            }
        }
    }
}

TEST(CatmullRom, EndTangentsAreTheEndChords) {
    std::mt19937_64 rng(6);
    const std::size_t n = 8;
    const auto q = random_vector(3 * n, rng);
    const auto start = eval(q, sp::weights_at(n, 0.0, Derivative::first));
    const auto end = eval(q, sp::weights_at(n, double(n - 1), Derivative::first));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(start[c], q[3 + c] - q[c], 1e-14);
        EXPECT_NEAR(end[c], q[3 * (n - 1) + c] - q[3 * (n - 2) + c], 1e-14);
    }
}

TEST(CatmullRom, LocateSplitsAndClampsTheParameter) {
    const std::size_t n = 6;
    std::size_t seg = 99;
    double t = -1.0;
    sp::locate(n, 2.25, &seg, &t);
    EXPECT_EQ(seg, 2u);
    EXPECT_DOUBLE_EQ(t, 0.25);
    sp::locate(n, 5.0, &seg, &t);  // the last point belongs to the last segment
    EXPECT_EQ(seg, 4u);
    EXPECT_DOUBLE_EQ(t, 1.0);
    sp::locate(n, 17.0, &seg, &t);
    EXPECT_EQ(seg, 4u);
    EXPECT_DOUBLE_EQ(t, 1.0);
    sp::locate(n, -3.0, &seg, &t);
    EXPECT_EQ(seg, 0u);
    EXPECT_DOUBLE_EQ(t, 0.0);
    sp::locate(n, std::nan(""), &seg, &t);
    EXPECT_EQ(seg, 0u);
    EXPECT_DOUBLE_EQ(t, 0.0);
}

}  // namespace
