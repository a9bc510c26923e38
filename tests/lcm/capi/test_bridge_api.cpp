// SPDX-License-Identifier: Apache-2.0
// The C API's contract (enteron_lcm.h): defaults, settings refused with a message that names
// them, a bad scene refused with libenteron's message, the feedback and stats accessors'
// errors, the workspace mapping seen end to end by a millimetre device with turned axes.
#include <cstring>
#include <string>

#include "bridge_test_support.h"

namespace enteron_lcm_test {
namespace {

TEST(BridgeApi, TheVersionIsTheLibrarysAndTheDefaultsAreTheDocumentedOnes) {
    EXPECT_EQ(ent_lcm_version(), static_cast<uint32_t>(ENT_VERSION));
    ent_lcm_bridge_desc desc;
    ent_lcm_bridge_desc_default(&desc);
    EXPECT_EQ(desc.struct_size, sizeof desc);
    EXPECT_EQ(desc.lcm_url, nullptr);
    EXPECT_DOUBLE_EQ(desc.tick_s, 0.001);
    EXPECT_DOUBLE_EQ(desc.watchdog_s, 0.030);
    EXPECT_DOUBLE_EQ(desc.force_ramp_s, 0.1);
    EXPECT_DOUBLE_EQ(desc.workspace_scale, 1.0);
    EXPECT_DOUBLE_EQ(desc.workspace_rotation_wxyz[0], 1.0);
    EXPECT_EQ(desc.mesh_skin_method, ENT_SKIN_CONVOLUTION);
    EXPECT_EQ(ent_lcm_bridge_desc_init(&desc, 12), ENT_ERROR_VERSION);
    EXPECT_EQ(ent_lcm_bridge_desc_init(nullptr, sizeof desc), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_GT(ent_lcm_monotonic_ns(), 0);
}

struct BadSetting {
    const char* field;
    void (*apply)(ent_lcm_bridge_desc&);
};

TEST(BridgeApi, EachBadSettingIsRefusedByName) {
    const BadSetting settings[] = {
        {"tick_s", [](ent_lcm_bridge_desc& d) { d.tick_s = 0.0; }},
        {"tick_s", [](ent_lcm_bridge_desc& d) { d.tick_s = std::nan(""); }},
        {"watchdog_s", [](ent_lcm_bridge_desc& d) { d.watchdog_s = -1.0; }},
        {"state_hz", [](ent_lcm_bridge_desc& d) { d.state_hz = 1e9; }},
        {"state_axis_points", [](ent_lcm_bridge_desc& d) { d.state_axis_points = 1; }},
        {"mesh_hz", [](ent_lcm_bridge_desc& d) { d.mesh_hz = -1.0; }},
        {"mesh_skin_method", [](ent_lcm_bridge_desc& d) { d.mesh_skin_method = 7; }},
        {"force_ramp_s", [](ent_lcm_bridge_desc& d) { d.force_ramp_s = 11.0; }},
        {"max_tool_speed_m_per_s", [](ent_lcm_bridge_desc& d) { d.max_tool_speed_m_per_s = 0.0; }},
        {"device_max_force", [](ent_lcm_bridge_desc& d) { d.device_max_force = -2.0; }},
        {"workspace_scale", [](ent_lcm_bridge_desc& d) { d.workspace_scale = 0.0; }},
        {"workspace_rotation_wxyz", [](ent_lcm_bridge_desc& d) { d.workspace_rotation_wxyz[0] = 0.0; }},
        {"workspace_offset_m", [](ent_lcm_bridge_desc& d) { d.workspace_offset_m[2] = INFINITY; }},
        {"force_scale", [](ent_lcm_bridge_desc& d) { d.force_scale = -1.0; }},
        {"realtime_priority", [](ent_lcm_bridge_desc& d) { d.realtime_priority = 100; }},
        {"scene_json", [](ent_lcm_bridge_desc& d) { d.scene_json = nullptr; }},
        {"lcm_url", [](ent_lcm_bridge_desc& d) { d.lcm_url = "nonsense://here"; }},
        {"journal_path", [](ent_lcm_bridge_desc& d) { d.journal_path = "/nonexistent/directory/journal"; }},
    };
    for (const BadSetting& setting : settings) {
        ent_lcm_bridge_desc desc = short_bowel_desc();
        setting.apply(desc);
        ent_lcm_bridge* bridge = reinterpret_cast<ent_lcm_bridge*>(&desc);  // untouched on failure
        EXPECT_EQ(ent_lcm_bridge_create(&desc, &bridge), ENT_ERROR_INVALID_ARGUMENT) << setting.field;
        EXPECT_NE(std::string(ent_lcm_last_error()).find(setting.field), std::string::npos)
            << setting.field << ": " << ent_lcm_last_error();
        EXPECT_EQ(bridge, reinterpret_cast<ent_lcm_bridge*>(&desc));
    }
}

TEST(BridgeApi, ABadSceneIsRefusedWithLibenteronsMessage) {
    ent_lcm_bridge_desc desc = short_bowel_desc();
    const char json[] = "{\"intestine\": {\"radius\": -1}}";
    desc.scene_json = json;
    desc.scene_json_length = sizeof json - 1;
    ent_lcm_bridge* bridge = nullptr;
    EXPECT_EQ(ent_lcm_bridge_create(&desc, &bridge), ENT_ERROR_INVALID_SCENE);
    EXPECT_NE(std::string(ent_lcm_last_error()).find("intestine.radius"), std::string::npos) << ent_lcm_last_error();
    EXPECT_EQ(bridge, nullptr);
}

TEST(BridgeApi, AccessorsRefuseWhatTheyCannotDo) {
    BridgePtr bridge = make_bridge(short_bowel_desc());
    ASSERT_TRUE(bridge);
    uint8_t buffer[512];
    size_t size = 0;
    EXPECT_EQ(ent_lcm_bridge_feedback(bridge.get(), 0, buffer, sizeof buffer, &size), ENT_ERROR_NOT_FOUND)
        << "no tick yet";
    ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), 1), ENT_OK);
    EXPECT_EQ(ent_lcm_bridge_feedback(bridge.get(), 1, buffer, sizeof buffer, &size), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_lcm_bridge_feedback(bridge.get(), 0, buffer, 10, &size), ENT_ERROR_BUFFER_TOO_SMALL);
    EXPECT_GT(size, 10u) << "the size needed is reported";
    EXPECT_EQ(ent_lcm_bridge_feedback(bridge.get(), 0, buffer, sizeof buffer, &size), ENT_OK);
    const enteron_tool_feedback_t f = feedback(bridge.get());
    EXPECT_EQ(f.status & ENTERON_TOOL_FEEDBACK_T_STATUS_NO_COMMAND, ENTERON_TOOL_FEEDBACK_T_STATUS_NO_COMMAND);
    EXPECT_EQ(f.command_seq, -1);
    void* lcm = nullptr;
    EXPECT_EQ(ent_lcm_bridge_lcm(bridge.get(), &lcm), ENT_ERROR_NOT_FOUND) << "lcm_url was \"\"";
    ent_lcm_stats s{};
    s.struct_size = 1;
    EXPECT_EQ(ent_lcm_bridge_stats(bridge.get(), &s), ENT_ERROR_VERSION);
    EXPECT_EQ(ent_lcm_bridge_stats(nullptr, &s), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_lcm_bridge_tick(nullptr, 0), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_lcm_bridge_scene(nullptr), nullptr);
    EXPECT_NE(ent_lcm_bridge_scene(bridge.get()), nullptr);
    EXPECT_EQ(ent_lcm_check_message(42, buffer, 3), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_lcm_check_message(ENT_LCM_SESSION, buffer, size), ENT_ERROR_INVALID_ARGUMENT);
    ent_lcm_bridge_notify(nullptr);
    ent_lcm_bridge_destroy(nullptr);
}

// A device reporting millimetres, its axes turned a quarter turn about the scene's x
// (device y is scene z: "up" for the device is its y), its origin 5 cm above the floor.
TEST(BridgeApi, TheWorkspaceMappingTakesDevicePosesInAndForcesOut) {
    ent_lcm_bridge_desc desc = short_bowel_desc();
    desc.workspace_scale = 0.001;
    desc.workspace_rotation_wxyz[0] = std::cos(M_PI / 4);
    desc.workspace_rotation_wxyz[1] = std::sin(M_PI / 4);
    desc.workspace_offset_m[2] = 0.05;
    BridgePtr bridge = make_bridge(desc);
    ASSERT_TRUE(bridge);
    // Pressing on the bowel (pressing_height): device x = -100 mm, device y = scene z - 50 mm.
    enteron_tool_command_t c = command(1, 1000 * kPressX_m, 0.0, 0.0);
    // The device's identity orientation is the quarter turn in the scene; send the inverse,
    // so the tool stays vertical.
    c.orientation_wxyz[0] = std::cos(M_PI / 4);
    c.orientation_wxyz[1] = -std::sin(M_PI / 4);
    int64_t now = 0;
    for (int64_t tick = 1; tick <= 400; ++tick) {
        now = tick * kMs;
        c.seq = tick;
        c.position_m[1] = 1000 * (pressing_height(tick) - 0.05);
        ASSERT_EQ(feed(bridge.get(), c, now), ENT_OK);
        ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), now), ENT_OK);
    }
    const enteron_tool_feedback_t f = feedback(bridge.get());
    EXPECT_NEAR(f.applied_position_m[0], -100.0, 1e-9) << "the applied pose, back in device millimetres";
    EXPECT_NEAR(f.applied_position_m[1], -26.0, 1e-9);
    EXPECT_NEAR(f.applied_position_m[2], 0.0, 1e-9);
    // The bowel pushes the tool up (scene +z): the device's +y.
    ASSERT_GT(magnitude(f.force_N), 0.05);
    EXPECT_GT(f.force_N[1], 0.9 * magnitude(f.force_N));
    EXPECT_LE(magnitude(f.force_N), kMaxForce_N + 1e-12);
    // The tool's stiffness (ent_tool_stiffness) travels too, mapped like the force: pressing
    // deeper (scene -z, device -y) pushes up harder, per device millimetre.
    double K[9];
    ASSERT_EQ(ent_tool_stiffness(ent_lcm_bridge_scene(bridge.get()), 0, K), ENT_OK) << ent_last_error();
    ASSERT_LT(K[8], -1.0) << "dF_z/dz in the scene, N/m";
    EXPECT_NEAR(f.stiffness_N_per_m[4], 0.001 * K[8], 1e-9 * std::fabs(K[8])) << "dF_y/dy on the device, N/mm";
}

}  // namespace
}  // namespace enteron_lcm_test
