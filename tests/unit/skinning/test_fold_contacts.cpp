// SPDX-License-Identifier: Apache-2.0
// The other folds near a point (lib/skinning/fold_contacts.h): found across a U-turn,
// never along a straight tube; their level is the distance to the axis in radii, to a
// small fraction of the chord's error on a bend; the own stretch of tube is let in
// continuously across the neighbour window.
#include "skinning/fold_contacts.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skinning/axis_samples.h"
#include "skinning/skin_axes.h"
#include "skinning/skin_fixtures.h"
#include "spline/arc_length.h"
#include "spline/catmull_rom.h"

namespace {

using namespace skin_test;
using enteron::Vec3;
using enteron::skinning::AxisSamples;
using enteron::skinning::FoldContacts;

struct Folds {
    explicit Folds(std::vector<double> axis) : points(std::move(axis)) {
        table.build(points.data(), points.size() / 3);
        samples.build(table, points.data(), points.size() / 3, AxisSamples::intervals_for(table.total_length(), 0.25 * R),
                      0.0, AxisSamples::Curvature::compute);
        folds.build(samples, R, 1.5 * R);
    }
    // The exact distance from p to the spline beyond `window` of arc length s (dense samples).
    double distance_beyond(const Vec3& p, double s, double window) const {
        double best = 1e300;
        const double length = table.total_length();
        for (int i = 0; i <= 200000; ++i) {
            const double a = length * i / 200000.0;
            if (std::fabs(a - s) < window) continue;
            const Vec3 q = enteron::spline::evaluate(
                points.data(), enteron::spline::weights_at(points.size() / 3, table.parameter_at(a),
                                                           enteron::spline::Derivative::value));
            best = std::min(best, (p - q).norm());
        }
        return best;
    }
    std::vector<double> points;
    enteron::spline::ArcLengthTable table;
    AxisSamples samples;
    FoldContacts folds;
};

TEST(FoldContacts, TheOtherLegOfAUTurnAndNothingAlongAStraightTube) {
    // Legs along x, 1.8 R apart (y = -0.9 R and +0.9 R), turning around x = 0.
    const Folds u_turn(u_turn_axis(0.2, 1.8 * R, 0.25 * R));
    const double s = 0.1;  // on the first leg, 0.1 m from the turn: at x = -0.1, y = -0.9 R
    const Vec3 centre{-0.1, -0.9 * R, 0.0};
    FoldContacts::Anchor anchors[8];
    ASSERT_EQ(u_turn.folds.near(centre, 0, s, anchors, 8), 1u);
    // On a ray towards the other leg, and across: o = distance / R, the gradient away from it.
    for (double t : {0.3 * R, 0.9 * R, 1.2 * R}) {
        for (double z : {0.0, 0.5 * R}) {
            const Vec3 p = centre + Vec3{0.0, t, z};
            Vec3 gradient;
            const double level = u_turn.folds.level(p, 0, s, anchors[0], &gradient);
            const double expected = std::hypot(1.8 * R - t, z) / R;
            EXPECT_NEAR(level, expected, 1e-9) << t / R << " " << z / R;
            EXPECT_NEAR(gradient.norm(), 1.0 / R, 1e-9);
            EXPECT_LT(gradient.y(), 0.0);
        }
    }
    // A straight tube has no other fold anywhere.
    const Folds straight(straight_axis(41, 0.025));
    for (double x : {0.0, 0.3, 1.0}) EXPECT_EQ(straight.folds.near(Vec3{x, 0.0, 0.0}, 0, x, anchors, 8), 0u) << x;
}

TEST(FoldContacts, BowedSegmentsFollowABendWithinAThousandthOfR) {
    // A coil of radius 3 R, 2.4 R a turn: the turn above is another fold. Its level from a
    // point between the turns matches the distance to the spline itself; the chords alone
    // (R / 4 apart) would be up to (R / 4)^2 / (8 * 3 R) = 2.6e-3 R off.
    const Folds coil(coil_axis(3.0 * R, 2.4 * R, 2.0, 0.25 * R));
    const double turn = std::hypot(2.0 * kPi * 3.0 * R, 2.4 * R);
    double worst = 0.0;
    for (int i = 0; i < 12; ++i) {
        const double s = 0.3 * turn + 0.05 * turn * i;
        const double angle = 2.0 * kPi * s / turn;
        const Vec3 centre{3.0 * R * std::cos(angle), 3.0 * R * std::sin(angle), 2.4 * R * s / turn};
        FoldContacts::Anchor anchors[8];
        const std::size_t count = coil.folds.near(centre, 0, s, anchors, 8);
        ASSERT_GE(count, 1u);
        for (double up : {0.6 * R, 1.0 * R}) {
            const Vec3 p = centre + Vec3{0.0, 0.0, up};
            double level = 1e300;
            for (std::size_t a = 0; a < count; ++a) {
                Vec3 gradient;
                level = std::min(level, coil.folds.level(p, 0, s, anchors[a], &gradient));
            }
            worst = std::max(worst, std::fabs(level * R - coil.distance_beyond(p, s, kPi * R)) / R);
        }
    }
    EXPECT_LT(worst, 1e-3);
}

TEST(FoldContacts, TheOwnTubeEntersContinuouslyAcrossTheWindow) {
    // The level of a point near the U-turn seen from arc lengths sliding along the leg: the
    // other leg's nearest part moves from inside the window (penalised) to beyond it.
    const Folds u_turn(u_turn_axis(0.2, 1.8 * R, 0.25 * R));
    const double turn_start = 0.2;  // arc length where the first leg reaches the turn
    const Vec3 p{-0.5 * R, 0.0, 0.0};  // between the legs, half a radius before the turn
    FoldContacts::Anchor anchors[8];
    const std::size_t count = u_turn.folds.near(Vec3{-0.5 * R, -0.9 * R, 0.0}, 0, turn_start - 0.5 * R, anchors, 8);
    ASSERT_GE(count, 1u);
    double previous = -1.0, largest_step = 0.0, smallest = 1e300, largest = 0.0;
    for (int i = 0; i <= 400; ++i) {
        const double s = turn_start - 0.5 * R - 3.0 * R + 6.0 * R * i / 400.0;  // sigma sweeps through [2 R, pi R]
        double level = 1e300;
        for (std::size_t a = 0; a < count; ++a) {
            Vec3 gradient;
            level = std::min(level, u_turn.folds.level(p, 0, s, anchors[a], &gradient));
        }
        if (previous >= 0.0) largest_step = std::max(largest_step, std::fabs(level - previous));
        previous = level;
        smallest = std::min(smallest, level);
        largest = std::max(largest, level);
    }
    EXPECT_LT(largest_step, 0.2);   // no jump (a step of the sweep is 0.015 R of arc)
    EXPECT_NEAR(smallest, 0.9, 0.05);  // fully another fold: the other leg 0.9 R away
    EXPECT_GT(largest, 2.0);           // penalised inside the window: beyond any bulge
}

}  // namespace
