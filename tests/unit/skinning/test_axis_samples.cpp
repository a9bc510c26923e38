// SPDX-License-Identifier: Apache-2.0
// The axis sampled evenly in arc length (lib/skinning/axis_samples.h): samples lie on the
// spline, a step apart in arc length, with unit tangents that are the spline's; on a
// circular arc their curvature vector points at the centre with length 1 / radius; the
// phantoms continue a straight end straight and a bent end along its osculating circle;
// samples at given arc lengths land there.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skinning/axis_samples.h"
#include "skinning/skin_axes.h"

namespace enteron::skinning {
namespace {

// Control points on a circle of radius r in the x-y plane, `count` of them over `angle` rad.
std::vector<double> axis_samples_arc_points(double r, double angle, std::size_t count) {
    std::vector<double> q;
    for (std::size_t i = 0; i < count; ++i) {
        const double a = angle * double(i) / double(count - 1);
        q.insert(q.end(), {r * std::cos(a), r * std::sin(a), 0.0});
    }
    return q;
}

TEST(AxisSamples, SamplesAreOnTheSplineEvenlyInArcLength) {
    const std::vector<double> q = axis_samples_arc_points(0.1, 2.0, 30);
    spline::ArcLengthTable table;
    table.build(q.data(), 30);
    AxisSamples samples;
    const std::size_t intervals = AxisSamples::intervals_for(table.total_length(), 0.01);
    EXPECT_EQ(intervals, std::size_t(std::lround(table.total_length() / 0.01)));
    samples.build(table, q.data(), 30, intervals, 0.0, AxisSamples::Curvature::compute);
    ASSERT_EQ(samples.size(), intervals + 1);
    EXPECT_EQ(samples.phantoms(), 0u);
    EXPECT_NEAR(samples.spacing() * double(intervals), table.total_length(), 1e-12);
    EXPECT_NEAR(samples.length(), table.total_length(), 1e-12);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double s = table.parameter_at(samples.arc_length(i));
        const spline::SegmentWeights w = spline::weights_at(30, s, spline::Derivative::value);
        ASSERT_LT((samples.position(i) - spline::evaluate(q.data(), w)).norm(), 1e-12) << "on the spline, sample " << i;
        const Vec3 d = spline::evaluate(q.data(), spline::weights_at(30, s, spline::Derivative::first));
        ASSERT_LT((samples.tangent(i) - d.normalized()).norm(), 1e-12);
        EXPECT_DOUBLE_EQ(samples.fraction(i), double(i) / double(intervals));
        // The control points are on a circle of 0.1 m; the spline between them nearly so,
        // away from the end segments (whose linear end treatment straightens them).
        const double s_ends = table.parameter_at(samples.arc_length(i));
        if (s_ends < 1.0 || s_ends > 28.0) continue;
        const Vec3 toward_centre = -Vec3(samples.position(i).x(), samples.position(i).y(), 0.0).normalized();
        EXPECT_NEAR(samples.curvature(i).norm(), 10.0, 0.2) << "1 / radius, sample " << i;
        EXPECT_GT(samples.curvature(i).normalized().dot(toward_centre), 0.999);
    }
}

TEST(AxisSamples, PhantomsContinueAStraightEndStraightAndABentOneOnItsCircle) {
    const std::vector<double> straight = skin_test::straight_axis(11, 0.025);
    spline::ArcLengthTable table;
    table.build(straight.data(), 11);
    AxisSamples samples;
    samples.build(table, straight.data(), 11, 25, 0.03, AxisSamples::Curvature::skip);
    const double step = samples.spacing();
    ASSERT_EQ(samples.phantoms(), std::size_t(std::ceil(0.03 / step)));
    ASSERT_EQ(samples.size(), 26 + 2 * samples.phantoms());
    const std::size_t p = samples.phantoms();
    for (std::size_t i = 0; i < p; ++i) {
        const Vec3 before = samples.position(p) - samples.tangent(p) * step * double(p - i);
        EXPECT_LT((samples.position(i) - before).norm(), 1e-12) << "straight on, phantom " << i;
        EXPECT_LT(samples.arc_length(i), 0.0);
    }
    // A bent end: the phantoms stay on the circle the end osculates (radius 0.1 m here).
    const std::vector<double> bent = axis_samples_arc_points(0.1, 1.5, 20);
    table.build(bent.data(), 20);
    samples.build(table, bent.data(), 20, 30, 0.04, AxisSamples::Curvature::compute);
    const std::size_t last = samples.size() - 1;
    const Vec3 end = samples.position(last - samples.phantoms());
    const Vec3 k = samples.curvature(last - samples.phantoms());
    const Vec3 centre = end + k / k.squaredNorm();
    for (std::size_t i = last - samples.phantoms() + 1; i <= last; ++i)
        EXPECT_NEAR((samples.position(i) - centre).norm(), 1.0 / k.norm(), 1e-9) << "on the osculating circle";
}

TEST(AxisSamples, SamplesAtGivenArcLengthsLandThere) {
    const std::vector<double> q = axis_samples_arc_points(0.2, 1.0, 12);
    spline::ArcLengthTable table;
    table.build(q.data(), 12);
    const double total = table.total_length();
    const std::vector<double> at = {0.0, 0.01, 0.05, 0.06, 0.5 * total, total};
    AxisSamples samples;
    samples.build_at(table, q.data(), 12, at, AxisSamples::Curvature::skip);
    ASSERT_EQ(samples.size(), at.size());
    EXPECT_EQ(samples.phantoms(), 0u);
    for (std::size_t i = 0; i < at.size(); ++i) {
        EXPECT_DOUBLE_EQ(samples.arc_length(i), at[i]);
        EXPECT_NEAR(table.length_at(table.parameter_at(at[i])), at[i], 1e-12);
        EXPECT_NEAR(samples.fraction(i), at[i] / total, 1e-15);
    }
    EXPECT_NEAR(samples.spacing(), total / double(at.size() - 1), 1e-12) << "the mean spacing";
}

}  // namespace
}  // namespace enteron::skinning
