// SPDX-License-Identifier: Apache-2.0
// What a grasp takes (lib/collision/grasp_aim.h): without jaws the centre nearest the tip;
// with jaws the one between them before a nearer one beside them, the one under them
// before a nearer one up a slope beside them, ties to the nearer to the tip; nothing beyond
// the reach, and never a NaN.
#include "collision/grasp_aim.h"

#include <gtest/gtest.h>

#include <limits>

namespace {

using enteron::Vec3;
using enteron::collision::GraspAim;
using enteron::collision::Jaws;

// A vertical tool at the origin (shaft up +z), jaws opening along x.
Jaws vertical_jaws(double length, double opening) {
    Jaws jaws;
    jaws.tip = Vec3::Zero();
    jaws.axis = Vec3::UnitZ();
    jaws.across = Vec3::UnitX();
    jaws.length = length;
    jaws.half_opening = 0.5 * opening;
    return jaws;
}

// Spheres of 1 cm radius offered to a 5 mm tool whose margin makes its reach `reach`.
std::size_t pick(const Jaws& jaws, double reach, std::initializer_list<Vec3> centres, bool* found) {
    const double tool_radius = 0.005, sphere_radius = 0.01;
    GraspAim aim(jaws, tool_radius, reach - tool_radius - sphere_radius);
    std::size_t i = 0;
    for (const Vec3& c : centres) aim.offer(i++, c, sphere_radius);
    *found = aim.found();
    return aim.picked();
}

}  // namespace

TEST(GraspAim, WithoutJawsItTakesTheCentreNearestTheTip) {
    bool found = false;
    const std::size_t picked = pick(vertical_jaws(0.0, 0.0), 0.02,
                                    {Vec3(0.018, 0.0, 0.0), Vec3(0.0, 0.016, 0.0), Vec3(0.0, 0.0, -0.017)}, &found);
    EXPECT_TRUE(found);
    EXPECT_EQ(picked, 1u);
}

TEST(GraspAim, JawsTakeTheCentreBetweenThemBeforeANearerOneBesideThem) {
    bool found = false;
    // Beside (y) at 1.6 cm; between (x, within the 2 cm opening's reach) at 1.8 cm, 1 cm up.
    const std::size_t picked =
        pick(vertical_jaws(0.02, 0.02), 0.02, {Vec3(0.0, 0.016, 0.0), Vec3(0.018, 0.0, 0.01)}, &found);
    EXPECT_TRUE(found);
    EXPECT_EQ(picked, 1u);
}

TEST(GraspAim, JawsTakeTheLoopUnderThemBeforeANearerOneUpASlopeBesideThem) {
    bool found = false;
    // Under the jaws 1.9 cm below the tip; 1.25 cm along x (beyond the 7.5 mm half opening)
    // and 5 mm higher: nearer the tip (1.5 cm), but off the aim.
    const std::size_t picked =
        pick(vertical_jaws(0.02, 0.015), 0.02, {Vec3(0.0125, 0.0, -0.014), Vec3(0.0, 0.0, -0.019)}, &found);
    EXPECT_TRUE(found);
    EXPECT_EQ(picked, 1u);
    // Without jaws the nearer is taken.
    EXPECT_EQ(pick(vertical_jaws(0.0, 0.0), 0.02, {Vec3(0.0125, 0.0, -0.014), Vec3(0.0, 0.0, -0.019)}, &found), 0u);
}

TEST(GraspAim, BetweenTheJawsTiesGoToTheCentreNearerTheTip) {
    bool found = false;
    // Both inside the jaws' rectangle (distance 0): the lower one.
    const std::size_t picked =
        pick(vertical_jaws(0.03, 0.02), 0.02, {Vec3(0.005, 0.0, 0.02), Vec3(0.005, 0.0, 0.004), Vec3(-0.005, 0.0, 0.01)},
             &found);
    EXPECT_TRUE(found);
    EXPECT_EQ(picked, 1u);
}

TEST(GraspAim, WithoutJawsAThinSphereIsReachedAtItsOwnSurface) {
    // A 5 mm tool, 5 mm margin: a 1.3 cm sphere 2.2 cm away (its surface 4 mm off the
    // tool's) against a 3.5 cm one 4.3 cm away (3 mm off): the surface, not the centre,
    // is nearer; each within its own reach (2.3 and 4.5 cm).
    GraspAim aim(vertical_jaws(0.0, 0.0), 0.005, 0.005);
    aim.offer(0, Vec3(0.022, 0.0, 0.0), 0.013);
    aim.offer(1, Vec3(0.0, 0.043, 0.0), 0.035);
    ASSERT_TRUE(aim.found());
    EXPECT_EQ(aim.picked(), 1u);
    EXPECT_DOUBLE_EQ(aim.picked_tip_distance2(), 0.043 * 0.043);
    // A thin sphere beyond its own reach (3 cm > 5 + 13 + 5 mm) is not taken, though a
    // sphere of the largest radius there would be.
    GraspAim thin(vertical_jaws(0.0, 0.0), 0.005, 0.005);
    thin.offer(0, Vec3(0.03, 0.0, 0.0), 0.013);
    EXPECT_FALSE(thin.found());
}

TEST(GraspAim, NothingBeyondTheReachAndNeverANaN) {
    bool found = true;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    pick(vertical_jaws(0.02, 0.02), 0.02, {Vec3(0.0, 0.021, 0.0), Vec3(nan, 0.0, 0.0), Vec3(0.0, 0.0, -0.03)}, &found);
    EXPECT_FALSE(found);
}
