// SPDX-License-Identifier: Apache-2.0
// "Simulate only the effects a scene calls for": an effect the scene does not name is never
// run, so its stats stay at zero however long the scene runs.
#include "capi_test_support.h"

using namespace capi_test;

namespace {

constexpr int kSteps = 100;

void expect_only_gravity_ran(const ent_scene* scene, uint64_t min_gravity_calls) {
    for (int32_t effect : {ENT_EFFECT_STRETCH, ENT_EFFECT_BEND, ENT_EFFECT_DAMPING, ENT_EFFECT_MESENTERY,
                           ENT_EFFECT_PINNED}) {
        const ent_effect_stats s = effect_stats(scene, effect);
        EXPECT_EQ(s.enabled, 0) << ent_effect_name(effect);
        EXPECT_EQ(s.calls, 0u) << ent_effect_name(effect);
        EXPECT_EQ(s.total_time_ns, 0u) << ent_effect_name(effect);
    }
    const ent_effect_stats g = effect_stats(scene, ENT_EFFECT_GRAVITY);
    EXPECT_EQ(g.enabled, 1);
    EXPECT_GE(g.calls, min_gravity_calls);
}

void expect_unknown_effects_not_found(const ent_scene* scene) {
    for (int32_t effect : {-1, ENT_EFFECT_COUNT, 99, -2147483647 - 1}) {
        ent_effect_stats s;
        std::memset(&s, 0x5a, sizeof s);
        s.struct_size = sizeof s;
        const ent_effect_stats before = s;
        EXPECT_EQ(ent_scene_effect_stats(scene, effect, &s), ENT_ERROR_NOT_FOUND) << effect;
        EXPECT_EQ(std::memcmp(&s, &before, sizeof s), 0) << "written on failure, effect " << effect;
        EXPECT_NE(std::string(ent_last_error()).find(std::to_string(effect)), std::string::npos)
            << "the message should name the effect: " << ent_last_error();
    }
}

TEST(EffectStats, JsonSceneWithOnlyGravityRunsOnlyGravity) {
    for (const char* integrator : {"rk4", "symplectic_euler", "implicit_euler"}) {
        SCOPED_TRACE(integrator);
        const std::string json = std::string(R"({
            "intestine": { "length": 1.0, "control_points": 20, "shape": { "kind": "line" },
                           "stretch_stiffness": 0, "bend_stiffness": 0 },
            "solver": { "integrator": ")") + integrator + R"(", "timestep": 0.001 },
            "gravity": [0, 0, -9.81]
        })";
        ScenePtr scene = create_json(json);
        ASSERT_TRUE(scene);
        // Before any step nothing has run.
        EXPECT_EQ(effect_stats(scene.get(), ENT_EFFECT_GRAVITY).calls, 0u);
        ASSERT_TRUE(step_n(scene.get(), 1e-3, kSteps));
        expect_only_gravity_ran(scene.get(), kSteps);
        expect_unknown_effects_not_found(scene.get());
    }
}

TEST(EffectStats, CDescWithOnlyGravityRunsOnlyGravity) {
    for (int32_t integrator : kIntegrators) {
        SCOPED_TRACE(integrator_name(integrator));
        ent_scene_desc desc = default_desc();
        desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
        desc.control_points = 20;
        desc.length_m = 1.0;
        desc.shape = ENT_SHAPE_LINE;
        desc.integrator = integrator;
        // Settings of effects that are not named must not matter, even absurd ones.
        desc.mesentery_attachments = 0;
        desc.drag_N_s_per_m2 = -1.0;
        desc.pinned_point_count = 3;
        desc.pinned_points = nullptr;
        ScenePtr scene = create(desc);
        ASSERT_TRUE(scene);
        ASSERT_TRUE(step_n(scene.get(), 1e-3, kSteps));
        expect_only_gravity_ran(scene.get(), kSteps);
        expect_unknown_effects_not_found(scene.get());
    }
}

TEST(EffectStats, NamedEffectsRunAndReportTheirCost) {
    ent_scene_desc desc = default_desc();
    static const uint32_t pins[1] = {5};
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                   ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_PINNED) |
                   ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    desc.control_points = 40;
    desc.length_m = 1.0;
    desc.mesentery_attachments = 10;
    desc.pinned_points = pins;
    desc.pinned_point_count = 1;
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    // The environment has no bit: its first obstacle turns it on.
    ent_obstacle_desc cavity;
    ent_obstacle_desc_default(&cavity);
    ASSERT_EQ(ent_scene_add_obstacle(scene.get(), &cavity, nullptr), ENT_OK) << ent_last_error();
    // Nor have the tools: the first tool turns them on.
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    tool.position_m[2] = 0.5;
    ASSERT_EQ(ent_tool_add(scene.get(), &tool, nullptr), ENT_OK) << ent_last_error();
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 20));
    for (int32_t effect = 0; effect < ENT_EFFECT_COUNT; ++effect) {
        const ent_effect_stats s = effect_stats(scene.get(), effect);
        EXPECT_EQ(s.enabled, 1) << ent_effect_name(effect);
        EXPECT_GE(s.calls, 20u) << ent_effect_name(effect);
    }
}

// The effects a description turns on by its bit: all but the environment, which starts
// with the first obstacle (ent_scene_add_obstacle), and the tools (ent_tool_add).
constexpr uint32_t kDescEffects = ((1u << ENT_EFFECT_COUNT) - 1u) & ~ENT_EFFECT_BIT(ENT_EFFECT_ENVIRONMENT) &
                                  ~ENT_EFFECT_BIT(ENT_EFFECT_TOOLS);

TEST(EffectStats, OnlyTheNamedEffectsAreEnabledForEverySubset) {
    // Every subset of the effects a description can name (pins need points to hold).
    static const uint32_t pins[1] = {0};
    for (uint32_t effects = 0; effects < (1u << ENT_EFFECT_COUNT); ++effects) {
        if ((effects & ~kDescEffects) != 0) continue;
        ent_scene_desc desc = default_desc();
        desc.effects = effects;
        desc.control_points = 8;
        desc.length_m = 0.5;
        desc.shape = ENT_SHAPE_LINE;
        desc.mesentery_attachments = 4;
        desc.pinned_points = pins;
        desc.pinned_point_count = 1;
        ScenePtr scene = create(desc);
        ASSERT_TRUE(scene) << "effects " << effects;
        ASSERT_TRUE(step_n(scene.get(), 1e-3, 3)) << "effects " << effects;
        for (int32_t effect = 0; effect < ENT_EFFECT_COUNT; ++effect) {
            const bool named = (effects & ENT_EFFECT_BIT(effect)) != 0;
            const ent_effect_stats s = effect_stats(scene.get(), effect);
            EXPECT_EQ(s.enabled, named ? 1 : 0) << "effects " << effects << ", " << ent_effect_name(effect);
            if (named) {
                EXPECT_GE(s.calls, 3u) << "effects " << effects << ", " << ent_effect_name(effect);
            } else {
                EXPECT_EQ(s.calls, 0u) << "effects " << effects << ", " << ent_effect_name(effect);
                EXPECT_EQ(s.total_time_ns, 0u) << "effects " << effects << ", " << ent_effect_name(effect);
            }
        }
    }
}

TEST(EffectStats, TheEnvironmentBitIsRefusedInADescription) {
    for (uint32_t effects : {ENT_EFFECT_BIT(ENT_EFFECT_ENVIRONMENT),
                             ENT_EFFECT_BIT(ENT_EFFECT_ENVIRONMENT) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY)}) {
        ent_scene_desc desc = default_desc();
        desc.effects = effects;
        desc.control_points = 8;
        desc.length_m = 0.5;
        ent_scene* scene = nullptr;
        EXPECT_EQ(ent_scene_create(&desc, &scene), ENT_ERROR_INVALID_ARGUMENT) << "effects " << effects;
        EXPECT_EQ(scene, nullptr);
        EXPECT_NE(std::string(ent_last_error()).find("effects"), std::string::npos) << ent_last_error();
        if (scene != nullptr) ent_scene_destroy(scene);
    }
}

}  // namespace
