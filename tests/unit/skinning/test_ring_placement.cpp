// SPDX-License-Identifier: Apache-2.0
// Ring placement (lib/skinning/ring_placement.h): rings come closer on a bend by the chord
// error bound.
#include "skinning/ring_placement.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skinning/skin.h"
#include "skinning/skin_axes.h"
#include "skinning/skin_fixtures.h"
#include "skinning/skin_metrics.h"

namespace {

using namespace skin_test;
using namespace enteron::skinning;
using skin_test::kPi;

TEST(RingPlacement, RingsComeCloserOnABendByTheChordErrorBound) {
    // A U-turn of radius rho = 3 R between straight legs: on the half circle the spacing is
    // sqrt(8 e / (k (1 + k R))) with k = 1 / rho; on the legs, away from the bend, the
    // largest spacing.
    const double rho = 3.0 * R, e = 0.01 * R, largest = 2.0 * R;
    const auto q = skin_test::u_turn_axis(0.2, 2.0 * rho, 0.25 * R);
    SkinSettings s = defaults(SkinMethod::convolution);
    auto skin = make_skin(s);  // for its arc-length table
    skin->update(q.data(), q.size() / 3);
    AxisSamples axis;
    axis.build(skin->arc_length(), skin->axis_points(), skin->axis_count(),
               AxisSamples::intervals_for(skin->arc_length().total_length(), 0.25 * R), 0.0,
               AxisSamples::Curvature::skip);
    RingPlacement placement;
    const std::vector<double>& rings = placement.place(axis, R, largest, 0.05 * R, e, 0);
    const double k = 1.0 / rho, bend = std::sqrt(8.0 * e / (k * (1.0 + k * R)));
    const double leg = 0.2, arc = kPi * rho;  // the half circle spans [leg, leg + arc] in arc length
    ASSERT_NEAR(rings.back(), 2 * leg + arc, 1e-3);
    EXPECT_EQ(rings.front(), 0.0);
    std::size_t on_bend = 0;
    for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
        const double a = rings[i], b = rings[i + 1], gap = b - a;
        ASSERT_GT(gap, 0.0);
        EXPECT_LE(gap, largest * 1.001);
        if (a > leg + 0.1 * arc && b < leg + 0.9 * arc) {  // well inside the bend
            EXPECT_NEAR(gap, bend, 0.1 * bend) << "at " << a;
            ++on_bend;
        }
        if (b < leg - 2 * largest || a > leg + arc + 2 * largest) {
            EXPECT_GT(gap, 0.9 * largest) << "at " << a;
        }
    }
    EXPECT_GT(on_bend, 10u);
}

TEST(RingPlacement, LevelsMoveInStepsWithHysteresis) {
    // U-turns of shrinking then growing radius: the count the bends need changes with
    // every one; in levels of 8 rings it is the next level up at once (never fewer rings
    // than needed), and drops only once a whole level is spare.
    const double e = 0.01 * R, largest = 2.0 * R;
    SkinSettings s = defaults(SkinMethod::convolution);
    auto skin = make_skin(s);
    RingPlacement free_rings, levelled;
    std::size_t previous_level = 0, changes = 0, shapes = 0;
    for (double rho : {6.0, 5.5, 5.0, 4.5, 4.0, 3.5, 3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0}) {
        const auto q = skin_test::u_turn_axis(0.2, 2.0 * rho * R, 0.25 * R);
        skin->update(q.data(), q.size() / 3);
        AxisSamples axis;
        axis.build(skin->arc_length(), skin->axis_points(), skin->axis_count(),
                   AxisSamples::intervals_for(skin->arc_length().total_length(), 0.25 * R), 0.0,
                   AxisSamples::Curvature::skip);
        const std::size_t needed = free_rings.place(axis, R, largest, 0.05 * R, e, 0).size() - 1;
        const std::size_t level = levelled.place(axis, R, largest, 0.05 * R, e, 8).size() - 1;
        EXPECT_EQ(level % 8, 0u);
        EXPECT_GE(level, needed) << "rho " << rho << " R";
        if (previous_level != 0 && level < previous_level) {
            EXPECT_GE(previous_level, needed + 8) << "dropped a level without a whole level spare";
        }
        if (previous_level != 0 && level != previous_level) ++changes;
        previous_level = level;
        ++shapes;
    }
    EXPECT_LT(changes, shapes - 1);  // the levels held over some of the changes of shape
}

}  // namespace
