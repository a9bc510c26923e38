// SPDX-License-Identifier: Apache-2.0
// How far a ring's ray may reach (lib/skinning/fold_over_limit.h): on a bend, up to the
// bend's axis; on a straight axis, anywhere; approached smoothly, never reached.
#include "skinning/fold_over_limit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using enteron::Vec3;
using enteron::skinning::below_fold_over_limit;
using enteron::skinning::fold_over_limit;

TEST(FoldOverLimit, OnACircleTheRayStopsOnTheBendsAxis) {
    // Ring centres on a circle of radius rho in the xy plane, around the origin; a ray from
    // the centre at angle 0, in the ring's plane, tilted by phi from the inward direction.
    const double rho = 0.01;
    for (double step : {0.001, 0.004}) {
        const Vec3 c{rho, 0.0, 0.0}, next{rho * std::cos(step / rho), rho * std::sin(step / rho), 0.0};
        for (double phi : {0.0, 0.5, 1.2}) {
            const Vec3 d{-std::cos(phi), 0.0, std::sin(phi)};  // inward, tilted out of the plane
            EXPECT_NEAR(fold_over_limit(c, d, next), rho / std::cos(phi), 1e-9) << step << " " << phi;
        }
        // Outwards: no limit.
        EXPECT_EQ(fold_over_limit(c, Vec3{1.0, 0.0, 0.0}, next), std::numeric_limits<double>::infinity());
    }
    // A straight axis: the neighbour lies along the tangent, no ray in the ring's plane approaches it.
    EXPECT_EQ(fold_over_limit(Vec3::Zero(), Vec3{0.0, 1.0, 0.0}, Vec3{0.001, 0.0, 0.0}),
              std::numeric_limits<double>::infinity());
}

TEST(FoldOverLimit, ApproachedSmoothlyNeverReached) {
    const double limit = 1.0;
    EXPECT_EQ(below_fold_over_limit(0.5, limit), 0.5);
    EXPECT_NEAR(below_fold_over_limit(0.9, limit), 0.9, 5e-5);
    EXPECT_NEAR(below_fold_over_limit(1.0, limit), 0.98, 0.005);
    EXPECT_LE(below_fold_over_limit(10.0, limit), 0.99 * limit);
    EXPECT_LE(below_fold_over_limit(1e6, limit), 0.99 * limit);
    EXPECT_EQ(below_fold_over_limit(2.0, std::numeric_limits<double>::infinity()), 2.0);
    // Never decreasing, continuous in t.
    double previous = 0.0;
    for (int i = 1; i <= 3000; ++i) {
        const double t = i * 1e-3, kept = below_fold_over_limit(t, limit);
        EXPECT_GE(kept, previous - 1e-15);  // to the last bits, where it saturates
        EXPECT_LT(kept - previous, 1.0001e-3);
        previous = kept;
    }
}

}  // namespace
