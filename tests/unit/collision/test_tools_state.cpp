// SPDX-License-Identifier: Apache-2.0
// Save and restore of the tools effect (lib/collision/tools_state.cpp): a tools effect
// restored from a saved one publishes the same outputs and goes on with the same bits; an
// image of another number of tools is refused with nothing changed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory_resource>
#include <vector>

#include "base/error.h"
#include "base/state_io.h"
#include "collision/collision_fixtures.h"
#include "collision/tools_force.h"

namespace {

using namespace collision_test;
using enteron::Vec3;
using namespace enteron::collision;

constexpr double kStateStep = 1e-3;  // s

// A proxy tool pressing on a straight bowel and holding it, stepped explicitly.
struct ToolsStateBench {
    explicit ToolsStateBench(int tools = 1)
        : axis(straight(21, 0.02)), spheres(axis.make_spheres()), channels(memory),
          effect(spheres, ContactParameters{}, axis.state, channels, memory) {
        for (int i = 0; i < tools; ++i) {
            ToolConfig tool;
            tool.pose.position = {0.1 + 0.1 * i, 0.0, kRadius + tool.settings.radius - 0.001};
            effect.add_tool(tool);
        }
    }
    // One accepted step of the tools alone; returns the generalised force.
    std::vector<double> step(const ToolPose* pose, bool grasp) {
        if (pose != nullptr) channels.mailbox(0)->post_pose(*pose);
        if (grasp) channels.mailbox(0)->post_grasp(ToolMailbox::Grasp::grasp);
        std::vector<double> force(axis.state.q.size(), 0.0);
        effect.take_commands(axis.state, kStateStep);
        effect.begin_attempt();
        enteron::mechanics::State at_end = axis.state;
        at_end.time += kStateStep;
        effect.evaluate(at_end, force.data(), nullptr);
        effect.evaluation_used(kStateStep, nullptr);
        effect.end_step(true);
        axis.state.time += kStateStep;
        return force;
    }
    std::vector<unsigned char> save() const {
        std::vector<unsigned char> image(1 << 16);
        enteron::StateWriter out(image.data(), image.size(), 7);
        effect.save_state(out);
        image.resize(out.finish());
        return image;
    }
    void restore(const std::vector<unsigned char>& image) {
        enteron::StateReader in(image.data(), image.size());
        effect.restore_state(in);
        in.finish();
        in.start_applying();
        effect.restore_state(in);
    }
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    Axis axis;
    CollisionSpheres spheres;
    ToolChannels channels;
    ToolsForce effect;
};

bool tools_state_same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(ToolsState, ARestoredToolsEffectPublishesTheSameAndGoesOnWithTheSameBits) {
    ToolsStateBench saved, restored;
    ToolPose pose;
    pose.position = {0.1, 0.0, kRadius + 0.002};
    saved.step(&pose, true);
    pose.position[2] += 0.002;
    saved.step(&pose, false);
    restored.axis.state.time = saved.axis.state.time;
    restored.restore(saved.save());
    const ToolOutput& a = saved.channels.outputs()[0];
    const ToolOutput& b = restored.channels.outputs()[0];
    EXPECT_EQ(a.wrench.force, b.wrench.force);
    EXPECT_TRUE(a.grasping);
    EXPECT_TRUE(b.grasping);
    EXPECT_EQ(a.proxy.position, b.proxy.position);
    EXPECT_EQ(a.stats.energy_in, b.stats.energy_in);
    pose.position[2] += 0.003;  // pulling on the grasp
    for (int k = 0; k < 3; ++k) {
        const std::vector<double> fa = saved.step(&pose, false), fb = restored.step(&pose, false);
        EXPECT_TRUE(tools_state_same_bits(fa, fb)) << k;
    }
    EXPECT_EQ(saved.channels.outputs()[0].wrench.force, restored.channels.outputs()[0].wrench.force);
    EXPECT_TRUE(restored.channels.outputs()[0].grasping) << "still holding";
}

TEST(ToolsState, AnImageOfAnotherNumberOfToolsIsRefusedWithNothingChanged) {
    ToolsStateBench one, two(2);
    ToolPose pose;
    pose.position = {0.1, 0.0, kRadius + 0.002};
    one.step(&pose, false);
    const ToolOutput before = two.channels.outputs()[0];
    try {
        two.restore(one.save());
        ADD_FAILURE() << "restored";
    } catch (const enteron::Error& e) {
        EXPECT_NE(std::string(e.what()).find("another number of tools"), std::string::npos) << e.what();
    }
    EXPECT_EQ(two.channels.outputs()[0].proxy.position, before.proxy.position);
}

}  // namespace
