// SPDX-License-Identifier: Apache-2.0
// The grasp law (lib/collision/tool_grasp.h) on its own: its force is minus the gradient of
// its energy (central finite differences) plus its damper; its Jacobian blocks are the
// derivatives of its force (H = -df/dp, df/dx with the tip's velocity following its move,
// C = -df/dv); its part of the implicit system is h^2 H + h C; slack, it does nothing; its
// rest length closes at kGraspClosingSpeed down to the tool's surface.
#include "collision/tool_grasp.h"

#include <gtest/gtest.h>

#include <functional>

namespace {

using enteron::Mat3;
using enteron::Vec3;
using namespace enteron::collision;

const GraspLaw kLaw{200.0, 2.0};
constexpr double kRest = 0.02;  // m
constexpr double kStep = 1e-7;  // m (or m/s) of the central differences

// Taut, along no axis, with velocities that make the damper pull too.
const Vec3 kTip(0.011, -0.004, 0.027), kTipVelocity(0.05, 0.01, -0.02);
const Vec3 kPoint(-0.002, 0.003, 0.001), kPointVelocity(-0.01, 0.03, 0.004);

// d g / d (each coordinate of x) by central differences, as columns.
Mat3 derivative(const std::function<Vec3(const Vec3&)>& g, const Vec3& x) {
    Mat3 d;
    for (int c = 0; c < 3; ++c) {
        Vec3 plus = x, minus = x;
        plus[c] += kStep;
        minus[c] -= kStep;
        d.col(c) = (g(plus) - g(minus)) / (2.0 * kStep);
    }
    return d;
}

TEST(ToolGrasp, ItsSpringForceIsMinusTheGradientOfItsEnergy) {
    const GraspLaw undamped{kLaw.stiffness, 0.0};
    const GraspSpring spring = grasp_spring(undamped, kRest, kTip, kTipVelocity, kPoint, kPointVelocity);
    ASSERT_TRUE(spring.taut);
    // f acts on the held point p: f = -dE/dp.
    Vec3 gradient;
    for (int c = 0; c < 3; ++c) {
        Vec3 plus = kPoint, minus = kPoint;
        plus[c] += kStep;
        minus[c] -= kStep;
        gradient[c] = (grasp_energy(undamped, kRest, kTip, plus) - grasp_energy(undamped, kRest, kTip, minus)) /
                      (2.0 * kStep);
    }
    EXPECT_LT((spring.force + gradient).norm(), 1e-6 * spring.force.norm());
    const double stretch = (kTip - kPoint).norm() - kRest;
    EXPECT_NEAR(grasp_energy(undamped, kRest, kTip, kPoint), 0.5 * kLaw.stiffness * stretch * stretch, 1e-15);
    EXPECT_NEAR(spring.force.norm(), kLaw.stiffness * stretch, 1e-12) << "pulls the point towards the tip";
    EXPECT_GT(spring.force.dot(kTip - kPoint), 0.0);
    // The damper adds c (v_x - v).
    const GraspSpring damped = grasp_spring(kLaw, kRest, kTip, kTipVelocity, kPoint, kPointVelocity);
    EXPECT_LT((damped.force - spring.force - kLaw.damping * (kTipVelocity - kPointVelocity)).norm(), 1e-15);
}

TEST(ToolGrasp, ItsJacobianBlocksAreTheDerivativesOfItsForce) {
    const GraspSpring spring = grasp_spring(kLaw, kRest, kTip, kTipVelocity, kPoint, kPointVelocity);
    const Mat3 stiffness = grasp_stiffness(spring);
    // H = -df/dp, velocities held.
    const Mat3 by_point = derivative(
        [](const Vec3& p) { return grasp_spring(kLaw, kRest, kTip, kTipVelocity, p, kPointVelocity).force; }, kPoint);
    EXPECT_LT((stiffness + by_point).norm(), 1e-6 * stiffness.norm()) << stiffness << "\n" << -by_point;
    EXPECT_LT((stiffness - stiffness.transpose()).norm(), 1e-12 * stiffness.norm()) << "symmetric";
    // df/dx with the tip's velocity (x - x0) / dt following it: H + c / dt I.
    const double dt = 1e-3;
    const Vec3 start = kTip - kTipVelocity * dt;
    const Mat3 by_tip = derivative(
        [&](const Vec3& x) {
            return grasp_spring(kLaw, kRest, x, (x - start) / dt, kPoint, kPointVelocity).force;
        },
        kTip);
    const Mat3 rate = grasp_tip_rate(spring, kLaw, 1.0 / dt);
    EXPECT_LT((rate - by_tip).norm(), 1e-6 * rate.norm()) << rate << "\n" << by_tip;
    EXPECT_LT((grasp_tip_rate(spring, kLaw, 0.0) - stiffness).norm(), 1e-12 * stiffness.norm());
    // C = -df/dv = c I.
    const Mat3 by_velocity = derivative(
        [](const Vec3& v) { return grasp_spring(kLaw, kRest, kTip, kTipVelocity, kPoint, v).force; },
        kPointVelocity);
    EXPECT_LT((by_velocity + kLaw.damping * Mat3::Identity()).norm(), 1e-6);
    // h^2 H + h C as axial n n^T + transverse I.
    const double h = 1e-3;
    const enteron::collision::ContactLinearization l = grasp_linearization(spring, kLaw, h);
    const Mat3 system = l.axial * spring.direction * spring.direction.transpose() + l.transverse * Mat3::Identity();
    EXPECT_LT((system - (h * h * stiffness + h * kLaw.damping * Mat3::Identity())).norm(), 1e-15);
}

TEST(ToolGrasp, SlackItPullsNothingAndStoresNothing) {
    const Vec3 near = kPoint + Vec3(0.0, 0.0, 0.5 * kRest);
    const GraspSpring spring = grasp_spring(kLaw, kRest, near, kTipVelocity, kPoint, kPointVelocity);
    EXPECT_FALSE(spring.taut);
    EXPECT_EQ(spring.force, Vec3::Zero()) << "not even its damper";
    EXPECT_EQ(grasp_stiffness(spring), Mat3::Zero());
    EXPECT_EQ(grasp_energy(kLaw, kRest, near, kPoint), 0.0);
}

TEST(ToolGrasp, ItsRestLengthClosesAtTheClosingSpeedDownToTheToolsSurface) {
    const double surface = 0.0175;  // m
    EXPECT_DOUBLE_EQ(grasp_rest(0.03, surface, 0.0), 0.03);
    EXPECT_DOUBLE_EQ(grasp_rest(0.03, surface, 0.1), 0.03 - kGraspClosingSpeed * 0.1);
    EXPECT_DOUBLE_EQ(grasp_rest(0.03, surface, 10.0), surface) << "never shorter than the surface";
}

}  // namespace
