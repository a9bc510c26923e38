// SPDX-License-Identifier: Apache-2.0
// Version handshake and status strings.
#include <enteron/enteron.h>
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <thread>

TEST(Version, LibraryMatchesHeader) {
    EXPECT_EQ(ent_version(), static_cast<uint32_t>(ENT_VERSION));
    EXPECT_EQ(ent_version() >> 16, static_cast<uint32_t>(ENT_VERSION_MAJOR));
    EXPECT_EQ((ent_version() >> 8) & 0xffu, static_cast<uint32_t>(ENT_VERSION_MINOR));
    EXPECT_EQ(ent_version() & 0xffu, static_cast<uint32_t>(ENT_VERSION_PATCH));
}

TEST(Status, EveryKnownStatusHasADistinctNonEmptyString) {
    std::set<std::string> seen;
    for (ent_status status = ENT_OK; status <= ENT_ERROR_BUSY; ++status) {
        const char* text = ent_status_string(status);
        ASSERT_NE(text, nullptr) << status;
        EXPECT_GT(std::strlen(text), 0u) << status;
        EXPECT_STRNE(text, "unknown status") << status;
        EXPECT_TRUE(seen.insert(text).second) << "status " << status << " repeats \"" << text << "\"";
    }
    EXPECT_EQ(seen.size(), 11u);
    EXPECT_STREQ(ent_status_string(ENT_OK), "ok");
}

TEST(Status, UnknownCodesGiveUnknownStatus) {
    for (ent_status status : {-1, 11, 12, 100, -2147483647 - 1, 2147483647})
        EXPECT_STREQ(ent_status_string(status), "unknown status") << status;
}

TEST(Status, LastErrorIsEmptyOnAThreadWhereNothingFailed) {
    std::string seen = "not run";
    std::thread([&] { seen = ent_last_error(); }).join();
    EXPECT_EQ(seen, "");
}

TEST(Status, LastErrorBelongsToTheFailingThreadAndSurvivesLaterSuccesses) {
    // A failure on this thread...
    ASSERT_EQ(ent_scene_step(nullptr, 1e-3), ENT_ERROR_INVALID_ARGUMENT);
    const std::string message = ent_last_error();
    EXPECT_NE(message, "");
    // ...is not seen by another thread...
    std::string other = "not run";
    std::thread([&] { other = ent_last_error(); }).join();
    EXPECT_EQ(other, "");
    // ...and a successful call does not clear it.
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.control_points = 10;
    desc.length_m = 1.0;
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    EXPECT_EQ(ent_last_error(), message);
    ent_scene_destroy(scene);
}

TEST(EffectName, KnownEffectsHaveTheirJsonNames) {
    const char* expected[ENT_EFFECT_COUNT] = {"stretch", "bend",   "damping",     "gravity",
                                              "mesentery", "pinned", "environment", "self_collision",
                                              "tools"};
    for (int32_t e = 0; e < ENT_EFFECT_COUNT; ++e) {
        ASSERT_NE(ent_effect_name(e), nullptr) << e;
        EXPECT_STREQ(ent_effect_name(e), expected[e]);
    }
    EXPECT_EQ(ent_effect_name(-1), nullptr);
    EXPECT_EQ(ent_effect_name(ENT_EFFECT_COUNT), nullptr);
    EXPECT_EQ(ent_effect_name(99), nullptr);
}

TEST(Defaults, DescDefaultMatchesTheHeaderDocumentation) {
    ent_scene_desc desc;
    std::memset(&desc, 0xab, sizeof desc);
    ent_scene_desc_default(&desc);
    EXPECT_EQ(desc.struct_size, sizeof desc);
    EXPECT_EQ(desc.effects, ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                                ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY));
    EXPECT_EQ(desc.length_m, 6.0);
    EXPECT_EQ(desc.radius_m, 0.0125);
    EXPECT_EQ(desc.control_points, 240u);
    EXPECT_EQ(desc.linear_density_kg_per_m, 0.3);
    EXPECT_EQ(desc.stretch_stiffness_N, 100.0);
    EXPECT_EQ(desc.bend_stiffness_N_m2, 2.5e-3);
    EXPECT_EQ(desc.shape, ENT_SHAPE_HELIX);
    EXPECT_EQ(desc.shape_direction[0], 1.0);
    EXPECT_EQ(desc.shape_points_xyz_m, nullptr);
    EXPECT_EQ(desc.integrator, ENT_INTEGRATOR_IMPLICIT_EULER);
    EXPECT_EQ(desc.timestep_s, 0.001);
    EXPECT_EQ(desc.max_substeps, 1000u);
    EXPECT_EQ(desc.max_subdivisions, 4u);
    EXPECT_EQ(desc.max_speed_m_per_s, 50.0);
    EXPECT_EQ(desc.gravity_m_per_s2[0], 0.0);
    EXPECT_EQ(desc.gravity_m_per_s2[1], 0.0);
    EXPECT_EQ(desc.gravity_m_per_s2[2], -9.81);
    EXPECT_EQ(desc.drag_N_s_per_m2, 0.05);
    EXPECT_EQ(desc.stretch_damping_N_s, 0.05);
    EXPECT_EQ(desc.bend_damping_N_m2_s, 0.0);
    EXPECT_EQ(desc.mesentery_root_start_m[0], -0.075);
    EXPECT_EQ(desc.mesentery_root_end_m[0], 0.075);
    EXPECT_EQ(desc.mesentery_attachments, 60u);
    EXPECT_EQ(desc.mesentery_stiffness_N_per_m, 5.0);
    EXPECT_EQ(desc.mesentery_rest_length_m, 0.0);
    EXPECT_EQ(desc.pinned_ends, ENT_PIN_NONE);
    EXPECT_EQ(desc.pinned_points, nullptr);
    EXPECT_EQ(desc.pinned_point_count, 0u);
    EXPECT_EQ(desc.callbacks, nullptr);

    ent_callbacks callbacks;
    std::memset(&callbacks, 0xab, sizeof callbacks);
    ent_callbacks_default(&callbacks);
    EXPECT_EQ(callbacks.struct_size, sizeof callbacks);
    EXPECT_EQ(callbacks.log, nullptr);
    EXPECT_EQ(callbacks.allocate, nullptr);
    EXPECT_EQ(callbacks.release, nullptr);
    EXPECT_EQ(callbacks.user_data, nullptr);

    ent_scene_desc_default(nullptr);  // ignored
    ent_callbacks_default(nullptr);
}

TEST(Defaults, TheDefaultSceneIsCreatedAndSteps) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    ASSERT_NE(scene, nullptr);
    for (int i = 0; i < 10; ++i) ASSERT_EQ(ent_scene_step(scene, 1e-3), ENT_OK) << ent_last_error();
    ent_stats s;
    s.struct_size = sizeof s;
    ASSERT_EQ(ent_scene_stats(scene, &s), ENT_OK);
    EXPECT_EQ(s.control_points, 240u);
    EXPECT_EQ(s.steps, 10u);
    EXPECT_NEAR(s.time_s, 0.01, 1e-15);
    EXPECT_GE(s.substeps, 10u);
    ent_scene_destroy(scene);
}
