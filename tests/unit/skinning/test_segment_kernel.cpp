// SPDX-License-Identifier: Apache-2.0
// The closed-form convolution of a segment with 1/r^3 (lib/skinning/segment_kernel.h)
// against a numerical integral.
#include "skinning/segment_kernel.h"

#include <gtest/gtest.h>

namespace {

using namespace enteron::skinning;
using enteron::Vec3;

TEST(SegmentKernel, MatchesNumericalIntegralOf1OverR3) {
    const Vec3 a{0.1, -0.2, 0.05}, b{0.4, 0.3, -0.1}, p{0.2, 0.35, 0.3};
    const int n = 200000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) / n;
        const Vec3 x = a + t * (b - a);
        const double r = (p - x).norm();
        sum += (b - a).norm() / n / (r * r * r);
    }
    EXPECT_NEAR(segment_field(p, a, b), sum, 1e-8 * sum);
    // Additive: two halves make the whole.
    const Vec3 m = 0.5 * (a + b);
    EXPECT_NEAR(segment_field(p, a, m) + segment_field(p, m, b), segment_field(p, a, b), 1e-12 * sum);
}

}  // namespace
