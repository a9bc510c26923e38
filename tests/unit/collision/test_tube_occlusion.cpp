// SPDX-License-Identifier: Apache-2.0
// Which sight lines a sampled tube hides (lib/collision/tube_occlusion.h): a line past the
// tube at a distance just above and just below the local radius, a radius that changes along
// the tube, and runs of hiding chords merged into one span when less than a diameter apart.
#include "collision/tube_occlusion.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using enteron::Vec3;
using enteron::collision::TubeOcclusion;

// A straight tube along x from -L/2 to L/2 at height h, `samples` samples, radii from r0 to r1.
TubeOcclusion tube_occlusion_straight(std::size_t samples, double length, double h, double r0, double r1) {
    std::vector<double> radii(samples);
    for (std::size_t i = 0; i < samples; ++i) radii[i] = r0 + (r1 - r0) * double(i) / double(samples - 1);
    TubeOcclusion tubes;
    tubes.add_tube(0, radii.data(), samples, 8);
    double* p = tubes.positions(0);
    for (std::size_t i = 0; i < samples; ++i) {
        p[3 * i] = -0.5 * length + length * double(i) / double(samples - 1);
        p[3 * i + 1] = 0.0;
        p[3 * i + 2] = h;
    }
    tubes.prepare();
    return tubes;
}

TEST(TubeOcclusion, AVerticalSightLineIsHiddenWithinTheRadiusAndSeenBeyondIt) {
    TubeOcclusion tubes = tube_occlusion_straight(41, 1.0, 0.05, 0.01, 0.01);
    tubes.reserve_sight_lines(2);
    const Vec3 eye(0.1, 0.00999, 0.3);  // a vertical line 0.00999 from the axis: hidden
    const double targets[6] = {0.1, 0.00999, 0.0, 0.1, 0.01001, 0.0};
    const double weights[2] = {1.0, 1.0};
    EXPECT_EQ(tubes.measure(eye, targets, weights, 1).hidden_lines, 1u);
    const Vec3 beside(0.1, 0.01001, 0.3);
    EXPECT_EQ(tubes.measure(beside, targets + 3, weights, 1).hidden_lines, 0u);
}

TEST(TubeOcclusion, TheRadiusIsTakenWhereTheSightLinePasses) {
    // Radius 1 cm at x = -0.5 m growing to 3 cm at x = +0.5 m: 2 cm at x = 0.
    TubeOcclusion tubes = tube_occlusion_straight(101, 1.0, 0.05, 0.01, 0.03);
    tubes.reserve_sight_lines(1);
    const double weights[1] = {1.0};
    for (double x : {-0.25, 0.0, 0.25}) {
        const double r = 0.02 + 0.02 * x;
        const double inside[3] = {x, 0.98 * r, 0.0}, outside[3] = {x, 1.02 * r, 0.0};
        EXPECT_EQ(tubes.measure(Vec3(x, 0.98 * r, 0.3), inside, weights, 1).hidden_lines, 1u) << x;
        EXPECT_EQ(tubes.measure(Vec3(x, 1.02 * r, 0.3), outside, weights, 1).hidden_lines, 0u) << x;
    }
}

TEST(TubeOcclusion, RunsLessThanADiameterApartAreOneSpanFartherApartTwo) {
    TubeOcclusion tubes = tube_occlusion_straight(201, 2.0, 0.05, 0.01, 0.01);  // chords of 1 cm
    tubes.reserve_sight_lines(2);
    const double weights[2] = {1.0, 3.0};
    // Two vertical sight lines at x apart; each hides the chords within 1 cm of it.
    for (const auto& [gap, spans] : {std::pair{0.035, 1u}, std::pair{0.07, 2u}}) {
        const double targets[6] = {0.0, 0.0, 0.0, gap, 0.0, 0.0};
        // An eye far above both: the lines are nearly vertical.
        const auto totals = tubes.measure(Vec3(0.5 * gap, 0.0, 1000.0), targets, weights, 2);
        EXPECT_EQ(totals.hidden_lines, 2u);
        EXPECT_EQ(totals.visible_weight, 0.0);
        ASSERT_EQ(tubes.spans().size(), spans) << "gap " << gap;
        double hidden = 0.0;
        for (const auto& span : tubes.spans()) hidden += span.hidden_weight;
        EXPECT_DOUBLE_EQ(hidden, 4.0) << "each line's weight counted once";
        EXPECT_LT(tubes.spans().front().u_first, 0.5);
        EXPECT_GT(tubes.spans().back().u_last, 0.5 + 0.5 * gap / 2.0);
    }
}

}  // namespace
