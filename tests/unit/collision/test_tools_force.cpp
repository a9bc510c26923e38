// The tools effect (lib/collision/tools_force.h) on its own: the force of a tool on the
// bowel and the wrench it reports are action and reaction, within max_force however deep
// the tool presses, with the torque of the contact points about the tip; and a grasp
// pulled past max_force slips: it adds no force and is let go when the step is accepted.
#include "collision/tools_force.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/collision_fixtures.h"
#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/tool.h"
#include "mechanics/state.h"

namespace {

using namespace collision_test;
using enteron::Vec3;
using enteron::collision::ToolConfig;
using enteron::collision::ToolPose;
using enteron::collision::ToolsForce;
using enteron::mechanics::State;

constexpr double kToolRadius = 0.005;
constexpr double kStep = 1e-3;  // s

std::vector<double> straight_axis(std::size_t n, double spacing) {
    std::vector<double> q;
    for (std::size_t i = 0; i < n; ++i) q.insert(q.end(), {spacing * double(i), 0.0, 0.0});
    return q;
}

// A straight bowel along x from 0 to 0.4 m, at rest, and the tools effect on it.
struct Bench {
    Bench()
        : axis(straight_axis(21, 0.02)),
          spheres(axis.make_spheres()),
          tools(spheres, contact, axis.state, std::pmr::new_delete_resource()) {}

    // One accepted step of the tools alone in which they stay put: the generalised force.
    std::vector<double> step() {
        std::vector<double> force(axis.state.q.size(), 0.0);
        tools.begin_step(axis.state.time, kStep);
        tools.begin_attempt();
        tools.evaluate(axis.state, force.data(), nullptr);
        tools.end_step();
        return force;
    }

    enteron::collision::ContactParameters contact;
    Axis axis;
    enteron::collision::CollisionSpheres spheres;
    ToolsForce tools;
};

// A tool along +x from x = -0.1 to 0.5, the whole bowel under its shaft, its axis `height`
// above the bowel's.
ToolConfig lying_tool(double height, double max_force) {
    ToolConfig tool;
    tool.settings.radius = kToolRadius;
    tool.settings.length = 0.6;
    tool.settings.max_force = max_force;
    tool.pose.position = {-0.1, 0.0, height};
    tool.pose.orientation = {std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0};  // local +z along world +x
    return tool;
}

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
        Bench bench;
        bench.tools.add_tool(lying_tool(kRadius + kToolRadius - depth, max_force));
        const Vec3 net = net_force(bench.step());
        const auto& wrench = bench.tools.wrench(0);
        const Vec3 on_tool(wrench.force[0], wrench.force[1], wrench.force[2]);
        const Vec3 torque(wrench.torque[0], wrench.torque[1], wrench.torque[2]);
        // Action and reaction.
        EXPECT_LT((on_tool + net).norm(), 1e-12 * max_force) << depth;
        // Every sphere lies under the shaft, pushed straight down with the contact law's
        // force: the bound holds, and is reached exactly once the contacts ask for more.
        const double asked = double(bench.spheres.size()) * bench.contact.stiffness * depth;
        EXPECT_NEAR(net.norm(), std::min(asked, max_force), 1e-9 * max_force) << depth;
        EXPECT_LE(net.norm(), max_force * (1.0 + 1e-12)) << depth;
        EXPECT_LT(net.z(), 0.0) << "the bowel is pushed down";
        EXPECT_NEAR(net.x(), 0.0, 1e-12);
        EXPECT_NEAR(net.y(), 0.0, 1e-12);
        // The torque about the tip: the contacts push the tool up along its length, on
        // average at the bowel's middle (x = 0.2), 0.3 m from the tip (x = -0.1).
        EXPECT_NEAR(torque.y(), -0.3 * on_tool.z(), 1e-9) << depth;
        EXPECT_NEAR(torque.x(), 0.0, 1e-12);
        EXPECT_NEAR(torque.z(), 0.0, 1e-12);
    }
}

TEST(ToolsForce, AGraspPulledPastMaxForceSlipsAddingNoForce) {
    Bench bench;
    // A vertical tool (the identity orientation) whose tip touches the bowel's middle.
    ToolConfig tool;
    tool.settings.max_force = 1.0;
    tool.pose.position = {0.2, 0.0, kRadius + tool.settings.radius};
    bench.tools.add_tool(tool);
    ASSERT_TRUE(bench.tools.grasp(0, bench.axis.state));
    // Lifted 0.3 m in one step: at the end of it the spring would pull k * 0.3 = 60 N.
    ToolPose lifted = tool.pose;
    lifted.position[2] += 0.3;
    bench.tools.set_target(0, lifted);
    State at_end = bench.axis.state;
    at_end.time += kStep;  // the tool has reached its target
    std::vector<double> force(at_end.q.size(), 0.0);
    bench.tools.begin_step(bench.axis.state.time, kStep);
    bench.tools.begin_attempt();
    bench.tools.evaluate(at_end, force.data(), nullptr);
    EXPECT_EQ(net_force(force).norm(), 0.0) << "a slipped grasp pulls nothing (and the tool is far above)";
    EXPECT_TRUE(bench.tools.grasping(0)) << "let go only when the step is accepted";
    bench.tools.end_step();
    EXPECT_FALSE(bench.tools.grasping(0));
}

}  // namespace
