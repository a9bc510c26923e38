// SPDX-License-Identifier: Apache-2.0
// The direct tool's contact law (lib/collision/tool_direct_contacts.h) on a straight bowel:
// every sphere under the shaft gets the penalty law's force, all scaled by one factor so that
// the sum of their magnitudes is at most max_force; a grasp whose spring alone needs more
// than max_force slips and adds nothing; the tool rests at the commanded tip.
#include "collision/tool_direct_contacts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory_resource>
#include <vector>

#include "collision/collision_fixtures.h"

namespace {

using namespace collision_test;
using enteron::Vec3;
using namespace enteron::collision;

constexpr double kToolRadius = 0.005;

// A direct tool along +x above the whole bowel (from x = -0.1 to 0.5), its axis `height` up.
ToolState lying_tool(double height, double max_force) {
    ToolState tool;
    tool.settings.radius = kToolRadius;
    tool.settings.length = 0.6;
    tool.settings.max_force = max_force;
    tool.settings.mode = ToolMode::direct;
    tool.current.position = {-0.1, 0.0, height};
    tool.current.orientation = {std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0};  // local +z along world +x
    tool.target = tool.current;
    return tool;
}

using Bench = ToolLawBench<DirectContacts>;

TEST(DirectContacts, EveryForceSharesOneScaleThatKeepsTheirSumWithinMaxForce) {
    for (const double depth : {1e-4, 5e-3}) {
        Bench bench;
        const double max_force = 2.0;
        ToolState tool = lying_tool(kRadius + kToolRadius - depth, max_force);
        bench.evaluate(tool);
        ASSERT_EQ(bench.contacts.size(), bench.spheres.size()) << "every sphere lies under the shaft";
        EXPECT_EQ(tool.evaluation.sphere_contacts, bench.spheres.size());
        // Every contact pushes straight down with the law's force at its depth, times one scale.
        const double asked = bench.contacts[0].depth * tool.contact.stiffness;
        double sum = 0.0;
        for (std::size_t k = 0; k < bench.contacts.size(); ++k) sum += bench.contacts[k].force.norm();
        const double scale = bench.contacts[0].force.norm() / asked;
        for (std::size_t k = 0; k < bench.contacts.size(); ++k) {
            EXPECT_NEAR(bench.contacts[k].force.norm(), scale * bench.contacts[k].depth * tool.contact.stiffness, 1e-12);
            EXPECT_LT(bench.contacts[k].force.z(), 0.0);
        }
        EXPECT_NEAR(sum, std::min(max_force, asked * double(bench.contacts.size())), 1e-9) << depth;
        EXPECT_EQ(tool.evaluation.rested.position, tool.current.position) << "the capsule is where it is put";
    }
}

TEST(DirectContacts, AGraspPulledPastMaxForceSlipsAndAddsNothing) {
    Bench bench;
    ToolState tool;
    tool.settings.max_force = 1.0;
    tool.settings.mode = ToolMode::direct;
    tool.current.position = tool.target.position = {0.2, 0.0, 0.3};  // far above the bowel's middle
    tool.grasp.holding = true;
    tool.grasp.point = bench.spheres[bench.spheres.size() / 2].weights;
    const double rest = kRadius + tool.settings.radius;
    bench.evaluate(tool, nullptr, rest);
    EXPECT_TRUE(tool.grasp.slipped) << "k (0.3 m - rest) = 56 N, past max_force";
    EXPECT_EQ(bench.contacts.size(), 0u);
    for (double f : bench.force) EXPECT_EQ(f, 0.0);
    // Within reach of max_force, it holds.
    ToolState near = tool;
    near.grasp.slipped = false;
    near.current.position = near.target.position = {0.2, 0.0, rest + 0.003};
    bench.evaluate(near, nullptr, rest);
    EXPECT_FALSE(near.grasp.slipped);
    ASSERT_EQ(bench.contacts.size(), 1u);
    EXPECT_EQ(bench.contacts[0].sphere, ToolContact::kGrasp);
    EXPECT_NEAR(bench.contacts[0].force.z(), near.settings.grasp_stiffness * 0.003, 1e-9) << "pulled up";
}

}  // namespace
