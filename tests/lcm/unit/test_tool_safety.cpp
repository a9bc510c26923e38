// SPDX-License-Identifier: Apache-2.0
// The safety rules of one tool (tool_safety.h), tick by tick, against the numbers they
// promise: the watchdog's time, the ramp's slope, the speed bounds, the clamps.
#include <gtest/gtest.h>

#include <cmath>

#include "lcm/tool_safety.h"

namespace enteron::lcm {
namespace {

constexpr int64_t kToolSafetyMs = 1000000;  // ns

class ToolSafetyTest : public ::testing::Test {
protected:
    ToolSafetyTest() { limits.tool_max_force_N = 5.0; }

    ToolSafety make() { return ToolSafety(limits, mapping, Pose{}); }

    // A command received at `received_ns` for the pose `position` (scene frame: identity mapping).
    AcceptedCommand command(int64_t seq, int64_t received_ns, Eigen::Vector3d position = Eigen::Vector3d::Zero(),
                            bool grasp = false, bool force_enable = true) {
        AcceptedCommand c;
        c.seq = seq;
        c.utime = 1000 + seq;
        c.received_ns = received_ns;
        c.scene_pose.position = position;
        c.grasp = grasp;
        c.force_enable = force_enable;
        return c;
    }

    static void render(ToolSafety& safety, double force_x, bool step_ok = true, bool saturated = false) {
        safety.render(Eigen::Vector3d(force_x, 0, 0), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), saturated,
                      step_ok);
    }

    SafetyLimits limits;
    WorkspaceMapping mapping;
};

TEST_F(ToolSafetyTest, WithoutACommandTheToolStaysAndRendersNothing) {
    ToolSafety safety = make();
    safety.plan(nullptr, 5 * kToolSafetyMs);
    render(safety, 3.0);
    EXPECT_EQ(safety.status() & kNoCommand, kNoCommand);
    EXPECT_FALSE(safety.live());
    EXPECT_EQ(safety.applied_pose().position, Eigen::Vector3d::Zero());
    EXPECT_EQ(safety.device_force(), Eigen::Vector3d::Zero());
    EXPECT_EQ(safety.device_stiffness(), Eigen::Matrix3d::Zero());
}

TEST_F(ToolSafetyTest, TheWatchdogTripsOnceJustAfterItsTimeAndHoldsTheTool) {
    ToolSafety safety = make();
    const AcceptedCommand first = command(1, 0, Eigen::Vector3d(0.0005, 0, 0));
    safety.plan(&first, 0);
    for (int64_t t = 1; t <= 30; ++t) {
        const ToolSafety::Plan plan = safety.plan(nullptr, t * kToolSafetyMs);
        render(safety, 1.0);
        ASSERT_TRUE(safety.live()) << "a command 30 ms old is not stale yet (t = " << t << " ms)";
        ASSERT_FALSE(plan.watchdog_tripped);
    }
    const Eigen::Vector3d held = safety.applied_pose().position;
    const ToolSafety::Plan plan = safety.plan(nullptr, 30 * kToolSafetyMs + 1);
    render(safety, 1.0);
    EXPECT_TRUE(plan.watchdog_tripped);
    EXPECT_EQ(safety.status() & kStale, kStale);
    EXPECT_EQ(safety.device_force(), Eigen::Vector3d::Zero());
    EXPECT_EQ(safety.applied_pose().position, held);
    EXPECT_FALSE(safety.plan(nullptr, 40 * kToolSafetyMs).watchdog_tripped) << "it trips once per stop";
}

TEST_F(ToolSafetyTest, TheForceRampsInOverTheRampTimeAndAgainAfterEveryStop) {
    ToolSafety safety = make();
    const double force = 2.0;
    for (int tick = 1; tick <= 150; ++tick) {
        const AcceptedCommand c = command(tick, tick * kToolSafetyMs);
        safety.plan(&c, tick * kToolSafetyMs);
        render(safety, force);
        const double expected = force * std::min(1.0, tick * limits.tick_s / limits.force_ramp_s);
        ASSERT_NEAR(safety.device_force().x(), expected, 1e-12) << "tick " << tick;
    }
    // 50 ms of silence: stale, zero; then commands again: from zero, one tick's share first.
    safety.plan(nullptr, 200 * kToolSafetyMs);
    render(safety, force);
    EXPECT_EQ(safety.device_force().x(), 0.0);
    const AcceptedCommand back = command(151, 201 * kToolSafetyMs);
    safety.plan(&back, 201 * kToolSafetyMs);
    render(safety, force);
    EXPECT_NEAR(safety.device_force().x(), force * limits.tick_s / limits.force_ramp_s, 1e-12);
}

TEST_F(ToolSafetyTest, TheToolMovesTowardAJumpAtItsSpeedBound) {
    ToolSafety safety = make();
    const Eigen::Vector3d target(0.1, 0, 0);  // 10 cm away: 100 ticks at 1 m/s
    const AcceptedCommand c = command(1, 0, target);
    safety.plan(&c, 0);
    EXPECT_NEAR(safety.applied_pose().position.x(), 0.001, 1e-15);
    EXPECT_EQ(safety.status() & kRateLimited, kRateLimited);
    for (int tick = 2; tick <= 99; ++tick) safety.plan(nullptr, tick * kToolSafetyMs / 10);
    EXPECT_NEAR(safety.applied_pose().position.x(), 0.099, 1e-12);
    safety.plan(nullptr, 10 * kToolSafetyMs);
    safety.plan(nullptr, 11 * kToolSafetyMs);
    EXPECT_EQ(safety.applied_pose().position, target);
    EXPECT_EQ(safety.status() & kRateLimited, 0);
}

TEST_F(ToolSafetyTest, TheToolTurnsAtItsAngularSpeedBound) {
    ToolSafety safety = make();
    AcceptedCommand c = command(1, 0);
    c.scene_pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
    safety.plan(&c, 0);
    const double per_tick = limits.max_angular_speed_rad_per_s * limits.tick_s;
    EXPECT_NEAR(safety.applied_pose().orientation.angularDistance(Eigen::Quaterniond::Identity()), per_tick, 1e-12);
    // The same rotation given as -q (same orientation) turns the short way, not around.
    AcceptedCommand opposite = command(2, 0);
    opposite.scene_pose.orientation.coeffs() = -c.scene_pose.orientation.coeffs();
    safety.plan(&opposite, 0);
    EXPECT_NEAR(safety.applied_pose().orientation.angularDistance(Eigen::Quaterniond::Identity()), 2 * per_tick, 1e-12);
}

TEST_F(ToolSafetyTest, ClampsToMaxForceToTheDeviceLimitAndToTheChangePerTick) {
    limits.force_ramp_s = 0.0;  // no ramp: the clamps alone
    limits.device_max_force = 3.0;
    limits.max_force_change_per_tick = 0.5;
    ToolSafety safety = make();
    const AcceptedCommand c = command(1, 0);
    safety.plan(&c, 0);
    render(safety, 0.2);
    EXPECT_NEAR(safety.device_force().x(), 0.2, 1e-15);
    EXPECT_EQ(safety.status() & kForceLimited, 0);
    render(safety, 8.0);  // over max_force (5), over the device (3), +2.8 in one tick
    EXPECT_NEAR(safety.device_force().x(), 0.7, 1e-12);
    EXPECT_EQ(safety.status() & kForceLimited, kForceLimited);
    for (int tick = 0; tick < 10; ++tick) render(safety, 8.0);
    EXPECT_NEAR(safety.device_force().x(), 3.0, 1e-12) << "at the device's limit";
    limits.device_max_force = 0.0;
    ToolSafety unlimited_device = make();
    unlimited_device.plan(&c, 0);
    for (int tick = 0; tick < 20; ++tick) render(unlimited_device, 8.0);
    EXPECT_NEAR(unlimited_device.device_force().x(), 5.0, 1e-12) << "at the tool's max_force";
}

// Issue 27, defect 6: libenteron bounds the force at max_force itself, so the force the
// bridge gets is exactly 5 N, which its own test (> max_force) misses; the library's
// saturated flag says it.
TEST_F(ToolSafetyTest, AForceTheLibraryBoundedIsSaidLimited) {
    limits.force_ramp_s = 0.0;
    ToolSafety safety = make();
    const AcceptedCommand c = command(1, 0);
    safety.plan(&c, 0);
    render(safety, 5.0);
    EXPECT_EQ(safety.status() & kForceLimited, 0) << "at max_force but not bounded: the contacts asked 5 N";
    safety.plan(nullptr, kToolSafetyMs);
    render(safety, 5.0, true, true);
    EXPECT_EQ(safety.status() & kForceLimited, kForceLimited);
    EXPECT_NEAR(safety.device_force().x(), 5.0, 1e-12) << "rendered as given";
    safety.plan(nullptr, 2 * kToolSafetyMs);
    render(safety, 5.0, false, true);
    EXPECT_EQ(safety.status() & kForceLimited, 0) << "a failed step renders nothing: nothing is limited";
}

TEST_F(ToolSafetyTest, StopsAreImmediateWhateverTheChangeLimit) {
    limits.force_ramp_s = 0.0;
    limits.max_force_change_per_tick = 0.01;
    ToolSafety safety = make();
    const AcceptedCommand c = command(1, 0);
    safety.plan(&c, 0);
    for (int tick = 0; tick < 200; ++tick) render(safety, 1.0);
    ASSERT_NEAR(safety.device_force().x(), 1.0, 1e-12);
    render(safety, 1.0, /*step_ok=*/false);
    EXPECT_EQ(safety.device_force(), Eigen::Vector3d::Zero()) << "an unstable step renders zero at once";
    EXPECT_EQ(safety.status() & kUnstable, kUnstable);
}

TEST_F(ToolSafetyTest, TheDeadmanRendersZeroAndTheForceRampsBackWhenPressed) {
    ToolSafety safety = make();
    const AcceptedCommand released = command(1, 0, Eigen::Vector3d::Zero(), false, false);
    safety.plan(&released, 0);
    render(safety, 2.0);
    EXPECT_EQ(safety.device_force(), Eigen::Vector3d::Zero());
    EXPECT_EQ(safety.status() & kForceDisabled, kForceDisabled);
    EXPECT_TRUE(safety.live()) << "the tool still follows the device";
    const AcceptedCommand pressed = command(2, kToolSafetyMs);
    safety.plan(&pressed, kToolSafetyMs);
    render(safety, 2.0);
    EXPECT_NEAR(safety.device_force().x(), 2.0 * limits.tick_s / limits.force_ramp_s, 1e-12);
}

TEST_F(ToolSafetyTest, GraspIsALevelActedOnOnlyWhenItChanges) {
    ToolSafety safety = make();
    AcceptedCommand c = command(1, 0, Eigen::Vector3d::Zero(), true);
    EXPECT_EQ(safety.plan(&c, 0).grasp_action, GraspAction::grasp);
    c.seq = 2;
    EXPECT_EQ(safety.plan(&c, kToolSafetyMs).grasp_action, GraspAction::none) << "still closed: no new grasp";
    EXPECT_EQ(safety.plan(nullptr, 2 * kToolSafetyMs).grasp_action, GraspAction::none);
    // Stale: an opening that is not there is not acted on; the jaws stay closed.
    EXPECT_EQ(safety.plan(nullptr, 100 * kToolSafetyMs).grasp_action, GraspAction::none);
    EXPECT_TRUE(safety.jaws_closed());
    AcceptedCommand open = command(3, 101 * kToolSafetyMs, Eigen::Vector3d::Zero(), false);
    EXPECT_EQ(safety.plan(&open, 101 * kToolSafetyMs).grasp_action, GraspAction::release);
    EXPECT_FALSE(safety.jaws_closed());
}

}  // namespace
}  // namespace enteron::lcm
