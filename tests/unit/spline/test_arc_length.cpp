// SPDX-License-Identifier: Apache-2.0
// Arc length along the spline (lib/spline/arc_length.h).
#include "spline/arc_length.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "spline/catmull_rom.h"
#include "spline/spline_reference.h"

namespace {

using enteron::spline::ArcLengthTable;

constexpr double kArcLengthPi = 3.14159265358979323846;

std::vector<double> circle_points(std::size_t n, double radius) {
    // A closed circle: the first and the last control point coincide.
    std::vector<double> q(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const double a = 2 * kArcLengthPi * double(i) / double(n - 1);
        q[3 * i] = radius * std::cos(a);
        q[3 * i + 1] = radius * std::sin(a);
        q[3 * i + 2] = 0.1;
    }
    return q;
}

double circle_length_error(std::size_t n, double radius) {
    const auto q = circle_points(n, radius);
    ArcLengthTable table;
    table.build(q.data(), n);
    return std::fabs(table.total_length() - 2 * kArcLengthPi * radius) / (2 * kArcLengthPi * radius);
}

TEST(ArcLength, CircleLengthApproachesTwoPiR) {
    const double r = 0.3;
    // Interior segments follow the circle closely; the linearly extrapolated end tangents (the
    // end chords) are off by half a chord angle, an O(h^2) position error over the two end
    // segments of length O(h), so the total length converges like h^3.
    // Measured relative errors (total length vs 2 pi r): n = 17: 7.49e-4, 33: 7.80e-5,
    // 65: 8.67e-6, 129: 1.01e-6 (ratios 9.6, 9.0, 8.6); the bounds are twice those, and each
    // halving of h must divide the error by at least 6 (h^2.6).
    const std::size_t counts[] = {17, 33, 65, 129};
    const double bounds[] = {1.5e-3, 1.6e-4, 1.8e-5, 2.0e-6};
    double previous = 1.0;
    for (int k = 0; k < 4; ++k) {
        const double e = circle_length_error(counts[k], r);
        EXPECT_LT(e, bounds[k]) << "n " << counts[k];
        EXPECT_LT(e, previous / 6) << "n " << counts[k] << ": the error must fall like h^3";
        previous = e;
    }
}

TEST(ArcLength, TotalLengthMatchesAnIndependentIntegral) {
    // Simpson's rule on |P'(t)| of the docs/architecture.md formula, segment by segment (the speed is
    // smooth within a segment). Four points on a full circle (segments turning by 120 degrees)
    // is far coarser than any bowel; there the table's 5-point Gauss rule on eighths of a
    // segment was measured 9.1e-11 off (relative), so it gets a looser bound.
    const std::size_t counts[] = {4, 8, 17, 40};
    const double tolerances[] = {3e-10, 1e-11, 1e-11, 1e-11};
    for (int k = 0; k < 4; ++k) {
        const std::size_t n = counts[k];
        const auto q = circle_points(n, 0.3);
        const enteron_test::ReferenceSpline ref(q, 3);
        double expected = 0.0;
        for (std::size_t seg = 0; seg + 1 < n; ++seg)
            expected += enteron_test::simpson01([&](double t) {
                double s2 = 0.0;
                for (std::size_t c = 0; c < 3; ++c) s2 += ref.at(seg, t, 1, c) * ref.at(seg, t, 1, c);
                return std::sqrt(s2);
            });
        ArcLengthTable table;
        table.build(q.data(), n);
        EXPECT_NEAR(table.total_length(), expected, tolerances[k] * expected) << "n " << n;
    }
}

TEST(ArcLength, ParameterAtInvertsLengthAt) {
    const std::size_t n = 33;
    const auto q = circle_points(n, 0.3);
    ArcLengthTable table;
    table.build(q.data(), n);
    const double total = table.total_length();
    EXPECT_DOUBLE_EQ(table.length_at(0.0), 0.0);
    EXPECT_NEAR(table.length_at(double(n - 1)), total, 1e-14 * total);
    for (int k = 0; k <= 200; ++k) {
        const double target = total * k / 200.0;
        const double s = table.parameter_at(target);
        EXPECT_GE(s, 0.0);
        EXPECT_LE(s, double(n - 1));
        EXPECT_NEAR(table.length_at(s), target, 1e-11 * total) << "k " << k;
    }
    // Clamped outside the axis.
    EXPECT_EQ(table.parameter_at(-1.0), 0.0);
    EXPECT_EQ(table.parameter_at(2 * total), double(n - 1));
}

TEST(ArcLength, StraightEvenlySpacedLineHasItsChordLength) {
    const std::size_t n = 11;
    std::vector<double> q(3 * n);
    const double step[3] = {0.03, -0.04, 0.0};  // 0.05 m per segment
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) q[3 * i + c] = 1.0 + double(i) * step[c];
    ArcLengthTable table;
    table.build(q.data(), n);
    EXPECT_NEAR(table.total_length(), 0.5, 1e-14);
    for (double s : {0.0, 0.5, 3.25, 9.999, 10.0}) EXPECT_NEAR(table.length_at(s), 0.05 * s, 1e-14);
    EXPECT_NEAR(table.parameter_at(0.123), 0.123 / 0.05, 1e-11);
}

TEST(ArcLength, SampleEvenlyGivesEqualChordsOnAnUnevenlySpacedStraightLine) {
    // Collinear control points spaced unevenly (0.7 to 1.3 times the mean): the spline stays on
    // the line and its parameter is not proportional to length, so equal chords in the output
    // show that sampling inverts the arc length rather than stepping the parameter.
    const std::size_t n = 25;
    const double dir[3] = {2.0 / 3.0, -1.0 / 3.0, 2.0 / 3.0};
    std::vector<double> q(3 * n);
    double x = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) q[3 * i + c] = 0.2 + x * dir[c];
        x += 0.04 * (1.0 + 0.3 * std::sin(1.7 * double(i)));
    }
    const double length = std::sqrt((q[3 * (n - 1)] - q[0]) * (q[3 * (n - 1)] - q[0]) +
                                    (q[3 * (n - 1) + 1] - q[1]) * (q[3 * (n - 1) + 1] - q[1]) +
                                    (q[3 * (n - 1) + 2] - q[2]) * (q[3 * (n - 1) + 2] - q[2]));
    ArcLengthTable table;
    table.build(q.data(), n);
    EXPECT_NEAR(table.total_length(), length, 1e-12 * length);

    // The control points are not evenly spaced in arc length...
    const double chord0 = 0.04 * (1.0 + 0.3 * std::sin(0.0));
    const double chord1 = 0.04 * (1.0 + 0.3 * std::sin(1.7));
    ASSERT_GT(std::fabs(chord0 - chord1), 0.01);

    // ...but the samples are.
    const std::size_t samples = 57;
    std::vector<double> out(3 * samples);
    table.sample_evenly(samples, out.data());
    const double expected = length / double(samples - 1);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(out[c], q[c], 1e-14);
        EXPECT_NEAR(out[3 * (samples - 1) + c], q[3 * (n - 1) + c], 1e-14);
    }
    for (std::size_t i = 1; i < samples; ++i) {
        double d2 = 0.0, along = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double d = out[3 * i + c] - out[3 * (i - 1) + c];
            d2 += d * d;
            along += d * dir[c];
        }
        EXPECT_NEAR(std::sqrt(d2), expected, 1e-10 * length) << "sample " << i;
        EXPECT_GT(along, 0.0) << "samples must run from the first end to the last";
    }
}

}  // namespace

namespace {

TEST(ArcLength, TableFreeSamplingMatchesTheTable) {
    // spline::sample_evenly (no table, no allocation: what ent_scene_axis uses) must give the
    // same points as the table on a curved axis and on an unevenly spaced straight one.
    const std::size_t n = 33;
    std::vector<std::vector<double>> axes = {circle_points(n, 0.3)};
    std::vector<double> uneven(3 * n);
    double x = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        uneven[3 * i] = x;
        uneven[3 * i + 1] = 0.5 * x;
        x += 0.04 * (1.0 + 0.3 * std::sin(1.7 * double(i)));
    }
    axes.push_back(uneven);
    for (const auto& q : axes) {
        ArcLengthTable table;
        table.build(q.data(), n);
        for (std::size_t samples : {std::size_t(2), std::size_t(3), std::size_t(50), std::size_t(301)}) {
            std::vector<double> from_table(3 * samples), direct(3 * samples, -1.0);
            table.sample_evenly(samples, from_table.data());
            enteron::spline::sample_evenly(q.data(), n, samples, direct.data());
            for (std::size_t k = 0; k < 3 * samples; ++k)
                EXPECT_NEAR(direct[k], from_table[k], 1e-10 * table.total_length())
                    << "samples " << samples << " value " << k;
        }
    }
}

}  // namespace
