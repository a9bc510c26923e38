// SPDX-License-Identifier: Apache-2.0
// Rigid frames moved between steps: within a step the origin moves linearly and the
// orientation by nlerp, the velocity is the pose change over the step (or the one given),
// the frame rests at its target once the step is accepted and stays where it was if not,
// and a frame that has moved stays kinematic when it rests.
#include "mechanics/rigid_frames.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory_resource>

namespace {

using enteron::Vec3;
using enteron::mechanics::FramePlacement;
using enteron::mechanics::RigidFrames;
using enteron::mechanics::RigidPose;

TEST(RigidFrames, AFrameMovesWithinTheStepAndRestsAtItsTarget) {
    RigidFrames frames(std::pmr::new_delete_resource());
    const std::size_t f = frames.add(RigidPose{});
    EXPECT_TRUE(frames.at(f, 0.0).identity);
    EXPECT_FALSE(frames.at(f, 0.0).kinematic);

    RigidPose target;
    target.position = Vec3(0.01, 0.0, 0.0);
    target.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Vec3::UnitZ()));
    frames.set_target(f, target);
    const double t0 = 2.0, dt = 1e-3;
    frames.begin_step(t0, dt);
    const FramePlacement middle = frames.at(f, t0 + 0.5 * dt);
    EXPECT_TRUE(middle.moving);
    EXPECT_TRUE(middle.kinematic);
    EXPECT_NEAR(middle.origin.x(), 0.005, 1e-12);
    EXPECT_NEAR(middle.linear_velocity.x(), 10.0, 1e-9);         // 1 cm in 1 ms
    EXPECT_NEAR(middle.angular_velocity.z(), 100.0, 1e-9);       // 0.1 rad in 1 ms
    // A point 1 m along x of the frame moves at v + w x r.
    const Vec3 at = middle.to_world(Vec3::UnitX());
    EXPECT_NEAR(middle.velocity_at(at).y(), 100.0 * (at - middle.origin).x(), 1e-9);

    frames.end_step(false);  // refused: stays, target kept
    EXPECT_EQ(frames.pose(f).position, Vec3::Zero());
    frames.begin_step(t0, dt);
    frames.end_step(true);
    EXPECT_EQ(frames.pose(f).position, target.position);

    // At rest again: not moving, still kinematic (its contacts stay bounded).
    frames.begin_step(t0 + dt, dt);
    const FramePlacement resting = frames.at(f, t0 + 1.5 * dt);
    EXPECT_FALSE(resting.moving);
    EXPECT_TRUE(resting.kinematic);
    EXPECT_EQ(resting.velocity_at(Vec3::Zero()), Vec3::Zero());
}

TEST(RigidFrames, AGivenVelocityReplacesTheMotionsForOneStep) {
    RigidFrames frames(std::pmr::new_delete_resource());
    const std::size_t f = frames.add(RigidPose{});
    frames.set_velocity(f, Vec3(0.0, 0.2, 0.0), Vec3::Zero());  // a belt: slides, does not move
    frames.begin_step(0.0, 1e-3);
    EXPECT_NEAR(frames.at(f, 5e-4).velocity_at(Vec3::Zero()).y(), 0.2, 1e-15);
    EXPECT_EQ(frames.at(f, 5e-4).origin, Vec3::Zero());
    frames.end_step(true);
    frames.begin_step(1e-3, 1e-3);
    EXPECT_FALSE(frames.at(f, 1.5e-3).moving);
}

}  // namespace
