// SPDX-License-Identifier: Apache-2.0
// The tools effect (lib/collision/tools_force.h) on its own: the force of a tool on the
// bowel and the wrench it reports are action and reaction, within max_force however deep
// the tool presses, with the torque of the contact points about the tip; a grasp pulled
// past max_force slips: it adds no force and no energy, and is let go when the step is
// accepted; and the stiffness the tools publish is the derivative of their force (central
// finite differences, direct tools here and the proxy in tool_proxy's own solve).
#include "collision/tools_force.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/collision_fixtures.h"
#include "collision/collision_spheres.h"
#include "collision/tool_channels.h"
#include "mechanics/state.h"

namespace {

using namespace collision_test;
using enteron::Vec3;
using enteron::collision::ToolChannels;
using enteron::collision::ToolConfig;
using enteron::collision::ToolOutput;
using enteron::collision::ToolPose;
using enteron::collision::ToolsForce;

constexpr double kForceToolRadius = 0.005;
constexpr double kForceStep = 1e-3;  // s

// A straight bowel along x from 0 to 0.4 m at rest, and a tool lying along it above it.
struct ToolsForceBench {
    ToolsForceBench() : axis(straight(21, 0.02)), spheres(axis.make_spheres()), channels(memory), tools(spheres, contact, axis.state, channels, memory) {}

    // A tool along +x from x = -0.1 to 0.5 (the whole bowel under its shaft), its axis
    // `height` above the bowel's.
    static ToolConfig lying_tool(double height, double max_force) {
        ToolConfig tool;
        tool.settings.radius = kForceToolRadius;
        tool.settings.length = 0.6;
        tool.settings.max_force = max_force;
        tool.pose.position = {-0.1, 0.0, height};
        // Local +z along world +x: a quarter turn about y.
        tool.pose.orientation = {std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0};
        tool.settings.mode = enteron::collision::ToolMode::direct;  // the capsule where it is put
        return tool;
    }

    // One accepted step of the tools alone, evaluated at `state`: the generalised force and
    // the tool's output.
    std::vector<double> step(const enteron::mechanics::State& state, ToolOutput* output) {
        std::vector<double> force(state.q.size(), 0.0);
        tools.take_commands(axis.state, kForceStep);
        tools.begin_attempt();
        tools.evaluate(state, force.data(), nullptr);
        tools.evaluation_used(kForceStep, nullptr);  // one explicit evaluation over the whole step
        tools.end_step(true);
        *output = channels.outputs()[0];
        return force;
    }

    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    enteron::collision::ContactParameters contact;
    Axis axis;
    enteron::collision::CollisionSpheres spheres;
    ToolChannels channels;
    ToolsForce tools;
};

// The net force on the bowel: the generalised forces summed per coordinate (the basis
// weights of every spline point sum to one).
Vec3 net_force(const std::vector<double>& force) {
    Vec3 net = Vec3::Zero();
    for (std::size_t i = 0; i < force.size() / 3; ++i) net += enteron::point_at(force.data(), i);
    return net;
}

TEST(ToolsForce, TheWrenchIsMinusTheForceOnTheBowelAndNeverExceedsMaxForce) {
    const double max_force = 2.0;
    for (double depth : {1e-5, 1e-4, 1e-3, 5e-3, 1e-2}) {
        ToolsForceBench bench;
        bench.tools.add_tool(ToolsForceBench::lying_tool(kRadius + kForceToolRadius - depth, max_force));
        ToolOutput output;
        const Vec3 net = net_force(bench.step(bench.axis.state, &output));
        const Vec3 on_tool(output.wrench.force[0], output.wrench.force[1], output.wrench.force[2]);
        // Action and reaction.
        EXPECT_LT((on_tool + net).norm(), 1e-12 * max_force) << depth;
        // The bound, reached exactly once the contacts ask for more: every contact pushes
        // straight down, so the sum of their magnitudes is the net force.
        const double asked = double(output.contacts) * bench.contact.stiffness * depth;
        ASSERT_EQ(output.contacts, bench.spheres.size()) << "every sphere lies under the shaft";
        EXPECT_NEAR(net.norm(), std::min(asked, max_force), 1e-9 * max_force) << depth;
        EXPECT_LE(net.norm(), max_force * (1.0 + 1e-12)) << depth;
        EXPECT_LT(net.z(), 0.0) << "the bowel is pushed down";
        EXPECT_NEAR(net.x(), 0.0, 1e-12);
        EXPECT_NEAR(net.y(), 0.0, 1e-12);
        // The torque about the tip: the contacts push up on the tool along its length, on
        // average at the bowel's middle (x = 0.2), 0.3 m from the tip (x = -0.1).
        const Vec3 torque(output.wrench.torque[0], output.wrench.torque[1], output.wrench.torque[2]);
        EXPECT_NEAR(torque.y(), -0.3 * on_tool.z(), 1e-9) << depth;
        EXPECT_NEAR(torque.x(), 0.0, 1e-12);
        EXPECT_NEAR(torque.z(), 0.0, 1e-12);
    }
}

TEST(ToolsForce, AGraspPulledPastMaxForceSlipsAddingNoForceAndNoEnergy) {
    ToolsForceBench bench;
    // A vertical tool (the identity pose) whose tip touches the bowel's middle from above.
    ToolConfig tool;
    tool.settings.max_force = 1.0;
    tool.settings.mode = enteron::collision::ToolMode::direct;
    tool.pose.position = {0.2, 0.0, kRadius + tool.settings.radius};
    bench.tools.add_tool(tool);
    bench.channels.mailbox(0)->post_grasp(enteron::collision::ToolMailbox::Grasp::grasp);
    ToolOutput output;
    bench.step(bench.axis.state, &output);
    ASSERT_TRUE(output.grasping);
    // Lifted 0.3 m in one step: the spring would pull k * 0.3 = 60 N, past max_force.
    ToolPose lifted = tool.pose;
    lifted.position[2] += 0.3;
    bench.channels.mailbox(0)->post_pose(lifted);
    enteron::mechanics::State at_end = bench.axis.state;
    at_end.time = bench.axis.state.time + kForceStep;  // where the tool has reached the new pose
    std::vector<double> force(at_end.q.size(), 0.0);
    bench.tools.take_commands(bench.axis.state, kForceStep);
    bench.tools.begin_attempt();
    bench.tools.evaluate(at_end, force.data(), nullptr);
    // The grasp slipped: no force on the bowel (the tool is far above it) and no energy
    // stored in a spring that no longer holds, so the guard sees none appear.
    EXPECT_EQ(net_force(force).norm(), 0.0);
    // Nor any energy: the spring it let go of stores none that the guard could count.
    EXPECT_EQ(bench.tools.potential_energy(at_end), 0.0);
    bench.tools.end_step(true);
    EXPECT_FALSE(bench.channels.outputs()[0].grasping);
}

// The force on a direct tool resting at `tool` (no motion: velocities zero) and its stiffness.
struct Evaluated {
    Vec3 force;
    enteron::Mat3 stiffness;
};
Evaluated evaluate_at(const ToolConfig& tool, const enteron::mechanics::State& state) {
    ToolsForceBench bench;
    bench.tools.add_tool(tool);
    std::vector<double> force(state.q.size(), 0.0);
    bench.tools.evaluate(state, force.data(), nullptr);
    return {bench.tools.last_force(0), bench.tools.last_stiffness(0)};
}

// Central differences of the force, the tool moved by +-delta along each axis, against the
// stiffness; the largest relative error.
double stiffness_error(const ToolConfig& tool, const enteron::mechanics::State& state, double delta) {
    const Evaluated at = evaluate_at(tool, state);
    enteron::Mat3 differences;
    for (int j = 0; j < 3; ++j) {
        ToolConfig plus = tool, minus = tool;
        plus.pose.position[j] += delta;
        minus.pose.position[j] -= delta;
        differences.col(j) = (evaluate_at(plus, state).force - evaluate_at(minus, state).force) / (2 * delta);
    }
    return (differences - at.stiffness).norm() / std::max(1e-12, differences.norm());
}

TEST(ToolsForce, TheStiffnessOfADirectToolIsTheDerivativeOfItsForce) {
    ToolsForceBench bench;
    enteron::mechanics::State state = bench.axis.state;
    // The bowel bent a little and moving (friction and damping at work), so that normals
    // and slips differ from contact to contact.
    for (std::size_t i = 0; i < state.q.size() / 3; ++i) {
        state.q[3 * i + 1] = 0.01 * std::sin(10.0 * state.q[3 * i]);
        state.v[3 * i + 0] = 0.02;
        state.v[3 * i + 1] = -0.01;
    }
    struct Case {
        const char* name;
        ToolConfig tool;
    };
    ToolConfig vertical;  // one end pressing on the bowel from above
    vertical.settings.mode = enteron::collision::ToolMode::direct;
    vertical.settings.max_force = 100.0;
    vertical.pose.position = {0.2, 0.003, kRadius + vertical.settings.radius - 0.002};
    ToolConfig bounded = vertical;  // the same, within a bound it reaches
    bounded.settings.max_force = 0.3;
    ToolConfig slanted = vertical;  // across the bowel, a few spheres
    slanted.pose.orientation = {std::cos(0.6), std::sin(0.6), 0.0, 0.0};
    slanted.pose.position = {0.21, 0.004, kRadius + vertical.settings.radius - 0.003};
    const Case cases[] = {{"one end", vertical}, {"bounded", bounded}, {"across", slanted},
                          {"lying", ToolsForceBench::lying_tool(kRadius + kForceToolRadius - 0.001, 100.0)}};
    for (const Case& c : cases) {
        const Evaluated at = evaluate_at(c.tool, state);
        ASSERT_GT(at.force.norm(), 0.0) << c.name;
        const double error = stiffness_error(c.tool, state, 1e-7);
        std::cout << "[ stiffness " << c.name << " ] |F| " << at.force.norm() << " N, |K| " << at.stiffness.norm()
                  << " N/m, finite-difference error " << error << "\n";
        EXPECT_LT(error, 0.05) << c.name;
    }
}

}  // namespace
