// SPDX-License-Identifier: Apache-2.0
// The iso-value calibrated for the bend of the axis (lib/skinning/bend_calibration.h): on
// exact tight folds (arcs, U-turns, coils of radius 1.5 R to 4 R, the analytic tube of
// radius R as reference) both implicit skins stay within 1 % RMS of R.
#include "skinning/bend_calibration.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skinning/skin.h"
#include "skinning/skin_axes.h"
#include "skinning/skin_fixtures.h"
#include "skinning/skin_metrics.h"

namespace {

using namespace skin_test;
using namespace enteron::skinning;
using enteron::Vec3;

const char* name(SkinMethod m) { return m == SkinMethod::point_skeleton ? "point_skeleton" : "convolution"; }

TEST(BendCalibration, StraightIsOneAndTheOuterSideOfABendIsScaledUp) {
    // A window field like the convolution's: 1 / d^3 summed along the arc over [-R, R].
    BendCalibration bend;
    bend.build(R, [](double k, double c) {
        const Vec3 p = BendCalibration::point_off_arc(R, c);
        double sum = 0.0;
        for (int i = -200; i < 200; ++i) {
            const double s = (double(i) + 0.5) * R / 200.0;
            sum += (R / 200.0) / std::pow((p - BendCalibration::arc_point(k, s)).norm(), 3);
        }
        return sum;
    });
    for (double c : {-1.0, -0.3, 0.0, 0.7, 1.0}) EXPECT_NEAR(bend.scale(0.0, c), 1.0, 1e-12) << c;
    // The window's points are farther from the outer side (c = 1) and nearer to the inner
    // side of a bend: its field is weaker outside, stronger inside, by more on a tighter bend.
    const double k = 1.0 / (1.5 * R);
    EXPECT_GT(bend.scale(k, 1.0), bend.scale(k, 0.0));
    EXPECT_GT(bend.scale(k, 0.0), bend.scale(k, -1.0));
    EXPECT_GT(bend.scale(k, 1.0), bend.scale(0.5 * k, 1.0));
    EXPECT_GT(bend.scale(k, 1.0), 1.05);
    EXPECT_LT(bend.scale(k, -1.0), 0.9);
    // Beyond k R = 1 the table holds its last row.
    EXPECT_EQ(bend.scale(2.0 / R, 0.5), bend.scale(1.0 / R, 0.5));
    // The arc: unit speed, curvature k, through the origin along +x.
    const Vec3 a = BendCalibration::arc_point(k, 1e-4), b = BendCalibration::arc_point(k, 2e-4);
    EXPECT_NEAR((b - a).norm(), 1e-4, 1e-9);
    EXPECT_NEAR(BendCalibration::arc_point(k, 3.14159265358979 / k).y(), 2.0 / k, 1e-12);
}

TEST(BendCalibration, ImplicitSkinsWithinOnePercentOnTightFolds) {
    // Reference: the ideal tube of radius R around each axis (ent_skin_metrics' measure).
    struct Fold {
        const char* what;
        std::vector<double> axis;
    };
    const Fold folds[] = {
        {"U-turn of radius 1.5 R", u_turn_axis(0.1, 3.0 * R, 0.25 * R)},
        {"U-turn of radius 2 R", u_turn_axis(0.1, 4.0 * R, 0.25 * R)},
        {"coil of radius 2 R", coil_axis(2.0 * R, 2.4 * R, 3.0, 0.25 * R)},
        {"coil of radius 3 R", coil_axis(3.0 * R, 2.4 * R, 3.0, 0.25 * R)},
        {"coil of radius 4 R", coil_axis(4.0 * R, 2.4 * R, 2.0, 0.25 * R)},
    };
    for (SkinMethod method : {SkinMethod::point_skeleton, SkinMethod::convolution}) {
        auto skin = make_skin(defaults(method));
        for (const Fold& fold : folds) {
            const SkinMetrics m = skin_and_measure(*skin, fold.axis);
            EXPECT_LT(m.radius_error_rms, 0.01) << name(method) << ", " << fold.what;
            EXPECT_TRUE(m.watertight) << name(method) << ", " << fold.what;
            EXPECT_EQ(m.blended_vertices, 0u) << name(method) << ", " << fold.what;
        }
    }
}

}  // namespace
