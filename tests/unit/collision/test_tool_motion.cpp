// SPDX-License-Identifier: Apache-2.0
// A tool's commanded motion (lib/collision/tool_motion.h): the shaft leaves the step's start
// pose and reaches its target at the end, the tip in a straight line at the velocity of the
// pose change, turning along the shorter arc; between steps it rests at the start pose; and
// the travel that bounds a tool's work is the distance its ends and its turn cover.
#include "collision/tool_motion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using enteron::Vec3;
using namespace enteron::collision;

constexpr double kLength = 0.3;  // m

ToolPose tool_motion_pose(const Vec3& tip, double angle_about_y) {
    ToolPose p;
    p.position = tip;
    p.orientation = {std::cos(0.5 * angle_about_y), 0.0, std::sin(0.5 * angle_about_y), 0.0};
    return p;
}

TEST(ToolMotion, TheShaftGoesFromTheStartPoseToTheTargetWithinTheStep) {
    const ToolPose from = tool_motion_pose(Vec3(0.0, 0.0, 0.1), 0.0), to = tool_motion_pose(Vec3(0.02, -0.01, 0.08), 0.5);
    const StepSpan step{2.0, 1e-3};
    const ShaftAt start = commanded_shaft(from, to, kLength, step, 2.0);
    const ShaftAt end = commanded_shaft(from, to, kLength, step, 2.0 + 1e-3);
    EXPECT_EQ(start.tip, from.position);
    EXPECT_LT((start.tail - tail_of(from, kLength)).norm(), 1e-15);
    EXPECT_LT((end.tip - to.position).norm(), 1e-12);
    EXPECT_LT((end.tail - tail_of(to, kLength)).norm(), 1e-12);
    // Halfway: the tip halfway along the straight line; the shaft keeps its length.
    const ShaftAt half = commanded_shaft(from, to, kLength, step, 2.0 + 0.5e-3);
    EXPECT_LT((half.tip - 0.5 * (from.position + to.position)).norm(), 1e-12);
    EXPECT_NEAR((half.tail - half.tip).norm(), kLength, 1e-12);
    // The velocities are the pose change over the step, the same all through it.
    EXPECT_LT((half.tip_velocity - (to.position - from.position) / 1e-3).norm(), 1e-9);
    EXPECT_LT((half.tail_velocity - (tail_of(to, kLength) - tail_of(from, kLength)) / 1e-3).norm(), 1e-9);
    // Past the step's end it stays at the target.
    EXPECT_LT((commanded_shaft(from, to, kLength, step, 3.0).tip - to.position).norm(), 1e-15);
}

TEST(ToolMotion, BetweenStepsTheShaftRestsAtTheStartPose) {
    const ToolPose from = tool_motion_pose(Vec3(0.0, 0.0, 0.1), 0.2), to = tool_motion_pose(Vec3(0.05, 0.0, 0.1), 0.2);
    const ShaftAt at = commanded_shaft(from, to, kLength, StepSpan{}, 5.0);
    EXPECT_EQ(at.tip, from.position);
    EXPECT_EQ(at.tip_velocity, Vec3::Zero());
    EXPECT_EQ(at.tail_velocity, Vec3::Zero());
    EXPECT_EQ(StepSpan{}.elapsed(5.0), 0.0);
    EXPECT_EQ((StepSpan{1.0, 1e-3}).elapsed(0.5), 0.0) << "before the step";
}

TEST(ToolMotion, ItTurnsAlongTheShorterArc) {
    // The same rotation as q and -q: the target written with the opposite sign.
    const ToolPose from = tool_motion_pose(Vec3::Zero(), 0.2);
    ToolPose to = tool_motion_pose(Vec3::Zero(), 0.6);
    for (double& c : to.orientation) c = -c;
    const StepSpan step{0.0, 1.0};
    const ShaftAt half = commanded_shaft(from, to, kLength, step, 0.5);
    // Halfway through a turn about y from 0.2 to 0.6 rad: 0.4 rad (nlerp's angle is exact at
    // the midpoint of a turn).
    const Vec3 axis = (half.tail - half.tip) / kLength;
    EXPECT_NEAR(std::atan2(axis.x(), axis.z()), 0.4, 1e-12);
}

TEST(ToolMotion, TheTravelIsWhatTheEndsAndTheTurnCover) {
    const ToolPose from = tool_motion_pose(Vec3(0.0, 0.0, 0.0), 0.0);
    // Moved 3 cm along x, no turn: both ends go 3 cm, the turn nothing.
    ShaftTravel travel = commanded_travel(from, tool_motion_pose(Vec3(0.03, 0.0, 0.0), 0.0), kLength);
    EXPECT_NEAR(travel.tip, 0.03, 1e-15);
    EXPECT_NEAR(travel.tail, 0.03, 1e-15);
    EXPECT_NEAR(travel.turn, 0.0, 1e-15);
    // Turned by a about its tip: the tail moves along the chord 2 L sin(a / 2).
    const double a = 0.3;
    travel = commanded_travel(from, tool_motion_pose(Vec3::Zero(), a), kLength);
    EXPECT_NEAR(travel.tip, 0.0, 1e-15);
    EXPECT_NEAR(travel.tail, 2.0 * kLength * std::sin(0.5 * a), 1e-12);
    EXPECT_NEAR(travel.turn, travel.tail, 1e-15);
}

}  // namespace
