// SPDX-License-Identifier: Apache-2.0
// One set of defaults for JSON and C (issue 16, defect 7). Leaving out stretch_stiffness in
// JSON used to give a bowel without axial elasticity while the C defaults gave the elastic
// bowel; now both read the defaults of one place (lib/scene/scene_config.h), and an
// effect a scene does not ask for still costs nothing: a zero stiffness turns the bowel's
// elasticity off in both.
#include "capi_test_support.h"

using namespace capi_test;

namespace {

std::vector<double> trajectory(ent_scene* scene, int steps) {
    std::vector<double> all;
    for (int i = 0; i < steps; ++i) {
        EXPECT_EQ(ent_scene_step(scene, 1e-3), ENT_OK) << ent_last_error();
        const std::vector<double> q = control_points(scene);
        all.insert(all.end(), q.begin(), q.end());
    }
    return all;
}

void expect_same_effects(const ent_scene* a, const ent_scene* b) {
    for (int32_t e = 0; e < ENT_EFFECT_COUNT; ++e)
        EXPECT_EQ(effect_stats(a, e).enabled, effect_stats(b, e).enabled) << ent_effect_name(e);
}

TEST(Defaults, JsonNamingWhatTheCDefaultsTurnOnIsTheSameScene) {
    // The C default description turns on stretch, bend, damping and gravity. JSON names the
    // effects it wants; the bowel's elasticity it gets without asking, as C does.
    ScenePtr c = create(default_desc());
    ScenePtr json = create_json(R"({"gravity": [0, 0, -9.81], "damping": {}})");
    ASSERT_TRUE(c && json);
    expect_same_effects(c.get(), json.get());
    EXPECT_EQ(effect_stats(json.get(), ENT_EFFECT_STRETCH).enabled, 1);
    EXPECT_EQ(effect_stats(json.get(), ENT_EFFECT_BEND).enabled, 1);
    const std::vector<double> a = trajectory(c.get(), 100), b = trajectory(json.get(), 100);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << "not bit-identical";
}

TEST(Defaults, AnEmptyDocumentIsTheElasticBowelAndNothingElse) {
    ScenePtr scene = create_json("{}");
    ASSERT_TRUE(scene);
    for (int32_t e = 0; e < ENT_EFFECT_COUNT; ++e) {
        const bool elastic = e == ENT_EFFECT_STRETCH || e == ENT_EFFECT_BEND;
        EXPECT_EQ(effect_stats(scene.get(), e).enabled, elastic ? 1 : 0) << ent_effect_name(e);
    }
}

TEST(Defaults, AZeroStiffnessTurnsTheElasticityOffAndItCostsNothing) {
    ScenePtr json = create_json(R"({"intestine": {"stretch_stiffness": 0, "bend_stiffness": 0},
                                   "gravity": [0, 0, -9.81]})");
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
    desc.stretch_stiffness_N = 0.0;  // the bit asks, the zero does not: off, as in JSON
    desc.bend_stiffness_N_m2 = 0.0;
    ScenePtr c = create(desc);
    ASSERT_TRUE(json && c);
    for (ent_scene* scene : {json.get(), c.get()}) {
        ASSERT_TRUE(step_n(scene, 1e-3, 20));
        for (int32_t e : {ENT_EFFECT_STRETCH, ENT_EFFECT_BEND}) {
            const ent_effect_stats s = effect_stats(scene, e);
            EXPECT_EQ(s.enabled, 0) << ent_effect_name(e);
            EXPECT_EQ(s.calls, 0u) << ent_effect_name(e);
        }
    }
    const std::vector<double> a = trajectory(json.get(), 50), b = trajectory(c.get(), 50);
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
}

TEST(Defaults, ObstacleAndToolDefaultsAreTheSameInJsonAndC) {
    // A short bowel in the default cavity, a default sphere organ beside it and a default
    // tool above it, made once from JSON keys left out and once from the _default functions.
    const char* kBowel = R"("intestine": {"length": 0.3, "control_points": 12,
                           "shape": {"kind": "line", "center": [-0.15, 0, -0.1]}},
                           "gravity": [0, 0, -9.81], "damping": {})";
    ScenePtr json = create_json(std::string("{") + kBowel +
                                R"(, "environment": [{"type": "box_inside"}, {"type": "sphere", "center": [0, 0, 0.07]}],
                                     "tools": [{"position": [0, 0, -0.05]}]})");
    ent_scene_desc desc = default_desc();
    desc.length_m = 0.3;
    desc.control_points = 12;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_center_m[0] = -0.15;
    desc.shape_center_m[2] = -0.1;
    ScenePtr c = create(desc);
    ASSERT_TRUE(json && c);
    ent_obstacle_desc box, sphere;
    ent_obstacle_desc_default(&box);
    ent_obstacle_desc_default(&sphere);
    sphere.kind = ENT_OBSTACLE_SPHERE;
    sphere.center_m[2] = 0.07;
    ASSERT_EQ(ent_scene_add_obstacle(c.get(), &box, nullptr), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_scene_add_obstacle(c.get(), &sphere, nullptr), ENT_OK) << ent_last_error();
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    tool.position_m[2] = -0.05;
    ASSERT_EQ(ent_tool_add(c.get(), &tool, nullptr), ENT_OK) << ent_last_error();
    expect_same_effects(c.get(), json.get());
    const double down[3] = {0.0, 0.0, -0.09}, q[4] = {1.0, 0.0, 0.0, 0.0};
    for (ent_scene* scene : {json.get(), c.get()}) ASSERT_EQ(ent_tool_set_pose(scene, 0, down, q), ENT_OK);
    const std::vector<double> a = trajectory(json.get(), 200), b = trajectory(c.get(), 200);
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << "not bit-identical";
    EXPECT_GT(stats(c.get()).contacts, 0u) << "the tool and the cavity touch the bowel";
}

}  // namespace
