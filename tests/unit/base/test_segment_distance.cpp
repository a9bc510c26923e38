// SPDX-License-Identifier: Apache-2.0
// The closest points of two segments (lib/base/segment_distance.h) against a brute-force
// search over both parameters, for crossing, parallel, touching and degenerate segments.
#include "base/segment_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using enteron::closest_points_of_segments;
using enteron::Vec3;

// The smallest |P(s) - Q(t)|^2 on a fine grid, refined once around its best cell.
double brute_force(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
    double best = 1e300, bs = 0.0, bt = 0.0;
    const int n = 400;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const double s = double(i) / n, t = double(j) / n;
            const double d = ((p0 + s * (p1 - p0)) - (q0 + t * (q1 - q0))).squaredNorm();
            if (d < best) best = d, bs = s, bt = t;
        }
    for (int i = -50; i <= 50; ++i)
        for (int j = -50; j <= 50; ++j) {
            const double s = std::clamp(bs + i / (50.0 * n), 0.0, 1.0), t = std::clamp(bt + j / (50.0 * n), 0.0, 1.0);
            best = std::min(best, ((p0 + s * (p1 - p0)) - (q0 + t * (q1 - q0))).squaredNorm());
        }
    return best;
}

TEST(SegmentDistance, CrossingSegmentsMeetWhereTheyCross) {
    const auto c = closest_points_of_segments({-1, 0, 0}, {1, 0, 0}, {0.5, -1, 0.2}, {0.5, 1, 0.2});
    EXPECT_NEAR(c.s, 0.75, 1e-12);
    EXPECT_NEAR(c.t, 0.5, 1e-12);
    EXPECT_NEAR(c.distance_squared, 0.04, 1e-12);
}

TEST(SegmentDistance, ParallelAndDegenerateSegmentsGiveTheirDistance) {
    EXPECT_NEAR(closest_points_of_segments({0, 0, 0}, {1, 0, 0}, {0.5, 0.3, 0}, {2, 0.3, 0}).distance_squared, 0.09,
                1e-12);
    EXPECT_NEAR(closest_points_of_segments({0, 0, 0}, {0, 0, 0}, {1, -1, 0}, {1, 1, 0}).distance_squared, 1.0, 1e-12);
    EXPECT_NEAR(closest_points_of_segments({0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {3, 0, 0}).distance_squared, 4.0, 1e-12);
    EXPECT_NEAR(closest_points_of_segments({0, 0, 0}, {0, 0, 0}, {0, 0, 2}, {0, 0, 2}).distance_squared, 4.0, 1e-12);
}

TEST(SegmentDistance, RandomSegmentsMatchABruteForceSearch) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    auto point = [&] { return Vec3(coordinate(random), coordinate(random), coordinate(random)); };
    for (int k = 0; k < 30; ++k) {
        const Vec3 p0 = point(), p1 = point(), q0 = point(), q1 = point();
        const auto c = closest_points_of_segments(p0, p1, q0, q1);
        // Never above the search's best, and below it by no more than the search's grid allows.
        const double searched = brute_force(p0, p1, q0, q1);
        EXPECT_LE(c.distance_squared, searched + 1e-15) << "case " << k;
        EXPECT_GE(c.distance_squared, searched - 1e-6) << "case " << k;
        // The reported parameters give the reported distance.
        EXPECT_NEAR(((p0 + c.s * (p1 - p0)) - (q0 + c.t * (q1 - q0))).squaredNorm(), c.distance_squared, 1e-12);
    }
}

}  // namespace
