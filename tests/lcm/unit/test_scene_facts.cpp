// SPDX-License-Identifier: Apache-2.0
// The bridge's facts of its scene (scene_facts.h), asked of the scene: the radius and each
// tool's size, bound and initial pose as the library read them, defaults and the
// normalised quaternion included; a tool added after the JSON's is there too.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "base/error.h"
#include "lcm/scene_facts.h"

namespace enteron::lcm {
namespace {

struct SceneDeleter {
    void operator()(ent_scene* scene) const { ent_scene_destroy(scene); }
};

std::unique_ptr<ent_scene, SceneDeleter> make_scene(const std::string& json) {
    ent_scene* scene = nullptr;
    EXPECT_EQ(ent_scene_create_json(json.data(), json.size(), &scene), ENT_OK) << ent_last_error();
    return std::unique_ptr<ent_scene, SceneDeleter>(scene);
}

TEST(SceneFacts, AreTheScenesAsTheLibraryReadIt) {
    const auto scene = make_scene(R"({"intestine": {"radius": 0.011, "shape": {"helix_pitch": 0.03}},
        "tools": [{"radius": 0.004, "length": 0.2, "max_force": 2.5, "position": [0.3, 0, 0.4],
                   "orientation": [0, 0, 0, 3]},
                  {}]})");
    ASSERT_TRUE(scene);
    const SceneFacts facts = read_scene_facts(scene.get());
    EXPECT_EQ(facts.radius_m, 0.011);
    ASSERT_EQ(facts.tools.size(), 2u);
    const ToolFacts& first = facts.tools[0];
    EXPECT_EQ(first.radius_m, 0.004);
    EXPECT_EQ(first.length_m, 0.2);
    EXPECT_EQ(first.max_force_N, 2.5);
    EXPECT_EQ(first.initial_pose.position, Eigen::Vector3d(0.3, 0.0, 0.4));
    EXPECT_EQ(first.initial_pose.orientation.z(), 1.0) << "normalised by the library";
    EXPECT_EQ(first.initial_pose.orientation.w(), 0.0);
    // The second takes every default: ent_tool_desc_default's.
    ent_tool_desc defaults;
    ent_tool_desc_default(&defaults);
    EXPECT_EQ(facts.tools[1].radius_m, defaults.radius_m);
    EXPECT_EQ(facts.tools[1].max_force_N, defaults.max_force_N);
    EXPECT_EQ(facts.tools[1].initial_pose.orientation.w(), 1.0);
}

TEST(SceneFacts, ADefaultSceneHasTheDefaultRadiusAndNoTool) {
    const auto scene = make_scene("{}");
    ASSERT_TRUE(scene);
    const SceneFacts facts = read_scene_facts(scene.get());
    ent_scene_desc defaults;
    ent_scene_desc_default(&defaults);
    EXPECT_EQ(facts.radius_m, defaults.radius_m);
    EXPECT_TRUE(facts.tools.empty());
}

TEST(SceneFacts, AFailedQueryThrowsTheLibrarysStatusAndMessage) {
    try {
        read_scene_facts(nullptr);
        ADD_FAILURE() << "no error";
    } catch (const Error& error) {
        EXPECT_EQ(error.code(), ErrorCode::invalid_argument);
        EXPECT_EQ(std::string(error.what()).rfind("ent_scene_read_desc: scene", 0), 0u) << error.what();
    }
}

}  // namespace
}  // namespace enteron::lcm
