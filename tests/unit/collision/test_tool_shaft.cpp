// SPDX-License-Identifier: Apache-2.0
// A tool's shape (lib/collision/tool_shaft.h) with a retractor's blade, against brute
// force: its nearest point is the nearest of dense samples of the shaft and the blade, its
// continuous collision the first instant a fine sweep comes within reach, and without a
// blade it is the capsule.
#include "collision/tool_shaft.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

namespace {

using enteron::Vec3;
using enteron::collision::Blade;
using enteron::collision::Shaft;
using enteron::collision::ShaftPoint;

// A tilted tool: a 20 cm shaft, a 6 cm wide blade over its first 8 cm.
Shaft tilted_paddle(double reach) {
    const Vec3 tip(0.01, -0.02, 0.03);
    const Vec3 axis = Vec3(0.2, 0.5, 1.0).normalized() * 0.2;
    const Vec3 side = axis.cross(Vec3(1.0, 0.0, 0.0)).normalized() * 0.03;
    return Shaft(tip, tip + axis, reach, Blade{side, 0.4});
}

// The distance from p to the shaft and the blade, by sampling both every `step` of their
// parameters.
double sampled_distance(const Shaft& shaft, const Vec3& p, int samples) {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= samples; ++i) {
        const double s = static_cast<double>(i) / samples;
        best = std::min(best, (p - (shaft.tip + s * shaft.axis)).norm());
        for (int j = 0; j <= samples; ++j) {
            const double w = -1.0 + 2.0 * j / samples;
            best = std::min(best, (p - (shaft.tip + shaft.blade.along * s * shaft.axis + w * shaft.blade.side)).norm());
        }
    }
    return best;
}

}  // namespace

TEST(ToolShaft, ABladesNearestPointIsTheNearestOfDenseSamples) {
    const Shaft shaft = tilted_paddle(0.02);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> around(-0.12, 0.25);
    const int samples = 400;  // every 0.5 mm along the blade, 0.15 mm across
    for (int k = 0; k < 200; ++k) {
        const Vec3 p(around(random), around(random), around(random));
        ShaftPoint at;
        Vec3 d;
        double distance2;
        shaft.closest(p, &at, &d, &distance2);
        const double sampled = sampled_distance(shaft, p, samples);
        ASSERT_LE(std::sqrt(distance2), sampled + 1e-12) << "no sample is nearer than the nearest point";
        ASSERT_NEAR(std::sqrt(distance2), sampled, 3e-4) << "point " << k;
        // d runs from the nearest point, given by (s, w), to p.
        const Vec3 nearest = shaft.tip + at.s * shaft.axis + at.w * shaft.blade.side;
        ASSERT_LT((p - nearest - d).norm(), 1e-12);
        ASSERT_TRUE(at.w == 0.0 || at.s <= shaft.blade.along) << "only the blade is wide";
    }
}

TEST(ToolShaft, WithoutABladeItIsTheCapsule) {
    const Vec3 tip(0.0, 0.0, 0.0), tail(0.0, 0.0, 0.3);
    const Shaft capsule(tip, tail, 0.02);
    ShaftPoint at;
    Vec3 d;
    double distance2;
    capsule.closest(Vec3(0.05, 0.0, 0.1), &at, &d, &distance2);
    EXPECT_DOUBLE_EQ(std::sqrt(distance2), 0.05);
    EXPECT_DOUBLE_EQ(at.s, 0.1 / 0.3);
    EXPECT_TRUE(at.slides_along);
    EXPECT_FALSE(at.slides_across);
    EXPECT_EQ(at.w, 0.0);
    capsule.closest(Vec3(0.03, 0.04, -0.1), &at, &d, &distance2);  // below the tip: its cap
    EXPECT_DOUBLE_EQ(std::sqrt(distance2), std::sqrt(0.03 * 0.03 + 0.04 * 0.04 + 0.1 * 0.1));
    EXPECT_FALSE(at.slides_along);
}

TEST(ToolShaft, ABladesFirstTouchIsWhereAFineSweepFirstComesWithinReach) {
    const double radius = 0.015;
    const Shaft shaft = tilted_paddle(radius);
    const Vec3 middle = shaft.tip + 0.5 * shaft.blade.along * shaft.axis;
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), distance(0.03, 0.1), aim(-0.06, 0.06);
    int touched = 0, missed = 0;
    const int sweep = 20000;
    for (int k = 0; k < 400; ++k) {
        // From 3 to 10 cm off the blade's middle, towards a point up to 6 cm from it: the
        // blade's faces, edges and corners, the shaft, and misses.
        const Vec3 direction = Vec3(unit(random), unit(random), unit(random)).normalized();
        const Vec3 p = middle + distance(random) * direction;
        const Vec3 goal = middle + Vec3(aim(random), aim(random), aim(random));
        const Vec3 motion = 1.2 * (p - goal);  // the centre moves by -t motion relative to the tool
        ShaftPoint start;
        Vec3 d;
        double distance2;
        shaft.closest(p, &start, &d, &distance2);
        if (distance2 <= radius * radius) continue;  // starts touching: first_touch is 0
        const double t = shaft.first_touch(p, motion, radius);
        double swept = std::numeric_limits<double>::infinity();
        for (int i = 0; i <= sweep; ++i) {
            const double tau = static_cast<double>(i) / sweep;
            ShaftPoint at;
            shaft.closest(p - tau * motion, &at, &d, &distance2);
            if (distance2 <= radius * radius) {
                swept = tau;
                break;
            }
        }
        if (std::isinf(swept)) {
            ++missed;
            EXPECT_TRUE(std::isinf(t)) << "case " << k << ": touched at " << t << " though the sweep never is";
            continue;
        }
        ++touched;
        EXPECT_NEAR(t, swept, 1.5 / sweep) << "case " << k;
    }
    std::cout << "[ blade first touch ] " << touched << " touches, " << missed << " misses\n";
    EXPECT_GT(touched, 100) << "the cases test touches";
    EXPECT_GT(missed, 10) << "and misses";
}
