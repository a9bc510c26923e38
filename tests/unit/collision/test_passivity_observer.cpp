// SPDX-License-Identifier: Apache-2.0
// The passivity observer and limiter (lib/collision/passivity_observer.h) on their own: the
// work of the wrench on the commanded motion is split into energy in and out; the limiter
// keeps the balance non-negative within max_force and counts what it took.
#include "collision/passivity_observer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using enteron::Vec3;
using enteron::collision::PassivityObserver;
using enteron::collision::ToolWrench;

ToolWrench force(double x, double y, double z) {
    ToolWrench w;
    w.force = Vec3(x, y, z);
    return w;
}

TEST(PassivityObserver, CountsTheWorkInAndOut) {
    PassivityObserver observer;
    // Pushing into a 2 N reaction over 1 mm: 2 mJ in; then it pushes the tool back 1 mm: 2 mJ out.
    observer.observe(force(0, 0, 2), Vec3(0, 0, -1e-3), Vec3::Zero(), 5.0, false);
    EXPECT_NEAR(observer.stats().energy_in, 2e-3, 1e-15);
    EXPECT_EQ(observer.stats().energy_out, 0.0);
    observer.observe(force(0, 0, 2), Vec3(0, 0, 1e-3), Vec3::Zero(), 5.0, false);
    EXPECT_NEAR(observer.stats().energy_out, 2e-3, 1e-15);
    EXPECT_NEAR(observer.balance(), 0.0, 1e-15);
    EXPECT_EQ(observer.stats().largest_force_change, 2.0);
    // A torque does work on the turn.
    ToolWrench turning;
    turning.torque = Vec3(0, 0, 1);
    observer.observe(turning, Vec3::Zero(), Vec3(0, 0, -0.01), 5.0, false);
    EXPECT_NEAR(observer.stats().energy_in, 2e-3 + 0.01, 1e-15);
}

TEST(PassivityObserver, WithoutTheLimiterAnActiveSceneShowsADeficit) {
    PassivityObserver observer;
    // A force that pushes the tool along its motion: energy given to the device.
    for (int i = 0; i < 10; ++i) observer.observe(force(1, 0, 0), Vec3(1e-3, 0, 0), Vec3::Zero(), 5.0, false);
    EXPECT_NEAR(observer.balance(), -10e-3, 1e-15);
    EXPECT_EQ(observer.stats().limiter_energy, 0.0);
}

TEST(PassivityObserver, TheLimiterKeepsTheBalanceNonNegativeWithinMaxForce) {
    PassivityObserver observer;
    observer.observe(force(0, 0, 2), Vec3(0, 0, -1e-3), Vec3::Zero(), 5.0, true);  // 2 mJ in
    double largest = 0.0;
    for (int i = 0; i < 20; ++i) {
        const ToolWrench rendered = observer.observe(force(1, 0, 0), Vec3(1e-3, 0, 0), Vec3::Zero(), 5.0, true);
        largest = std::max(largest, rendered.force.norm());
        EXPECT_GE(observer.balance(), -1e-15) << i;
    }
    // The first 2 mJ the scene may give back as it is; the rest the damper takes out.
    EXPECT_NEAR(observer.stats().energy_out, 2e-3, 1e-12);
    EXPECT_NEAR(observer.stats().limiter_energy, 18e-3, 1e-12);
    EXPECT_LE(largest, 5.0 * (1 + 1e-12));
    // Beyond max_force the damper cannot hold the balance with the force alone: a torque
    // on the turn takes the rest.
    PassivityObserver bounded;
    const ToolWrench rendered = bounded.observe(force(1, 0, 0), Vec3(1e-3, 0, 0), Vec3(0.1, 0, 0), 1.0, true);
    EXPECT_LE(rendered.force.norm(), 1.0 + 1e-12);
    EXPECT_GE(bounded.balance(), -1e-15);
}

TEST(PassivityObserver, RotationBetweenQuaternions) {
    const double c = std::cos(0.25), s = std::sin(0.25);  // half of 0.5 rad
    const Vec3 turn = enteron::collision::rotation_between({1, 0, 0, 0}, {c, 0, 0, s});
    EXPECT_NEAR(turn.z(), 0.5, 1e-12);
    EXPECT_NEAR(turn.x(), 0.0, 1e-15);
    // The shorter arc: -q is the same rotation.
    const Vec3 same = enteron::collision::rotation_between({1, 0, 0, 0}, {-c, 0, 0, -s});
    EXPECT_NEAR((same - turn).norm(), 0.0, 1e-12);
}

}  // namespace
