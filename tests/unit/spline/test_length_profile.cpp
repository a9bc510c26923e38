// SPDX-License-Identifier: Apache-2.0
// A property along the length (lib/spline/length_profile.h): linear between its knots,
// constant past them, and its integrals exact.
#include "spline/length_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using enteron::spline::LengthProfile;

const LengthProfile kColon({0.0, 0.035, 0.3, 0.03, 1.5, 0.013}, std::pmr::get_default_resource());

TEST(LengthProfile, IsLinearBetweenItsKnotsAndConstantPastThem) {
    EXPECT_DOUBLE_EQ(kColon.at(0.0), 0.035);
    EXPECT_DOUBLE_EQ(kColon.at(0.15), 0.0325);
    EXPECT_DOUBLE_EQ(kColon.at(0.9), 0.0215);
    EXPECT_DOUBLE_EQ(kColon.at(-1.0), 0.035);
    EXPECT_DOUBLE_EQ(kColon.at(2.0), 0.013);
    EXPECT_DOUBLE_EQ(kColon.largest(), 0.035);
}

TEST(LengthProfile, IntegralsAgreeWithFineSums) {
    // Midpoint sums on a million intervals: second-order accurate, to about 1e-12 here.
    constexpr int kIntervals = 1000000;
    constexpr double kLength = 1.5;
    double value = 0.0, reciprocal = 0.0;
    for (int k = 0; k < kIntervals; ++k) {
        const double s = (k + 0.5) * kLength / kIntervals;
        value += kColon.at(s) * kLength / kIntervals;
        reciprocal += kLength / kIntervals / kColon.at(s);
    }
    EXPECT_NEAR(kColon.integral(kLength), value, 1e-9 * value);
    EXPECT_NEAR(kColon.reciprocal_integral(kLength), reciprocal, 1e-9 * reciprocal);
    // A length short of the last knot integrates only that far.
    EXPECT_NEAR(kColon.integral(0.3), 0.5 * (0.035 + 0.03) * 0.3, 1e-15);
}

TEST(LengthProfile, TheReciprocalIntegralIsInvertedWhereverItIsAsked) {
    for (const double s : {0.0, 0.1, 0.3, 0.31, 0.8, 1.5, 1.7}) {
        const double u = kColon.reciprocal_integral(s);
        EXPECT_NEAR(kColon.where_reciprocal_integral_is(u), s, 1e-12) << "s = " << s;
    }
    // A constant profile: u = s / R.
    const LengthProfile constant({0.0, 0.0125, 6.0, 0.0125}, std::pmr::get_default_resource());
    EXPECT_NEAR(constant.reciprocal_integral(3.0), 3.0 / 0.0125, 1e-9);
    EXPECT_NEAR(constant.where_reciprocal_integral_is(3.0 / 0.0125), 3.0, 1e-12);
}

}  // namespace
