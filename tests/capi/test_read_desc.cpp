// SPDX-License-Identifier: Apache-2.0
// Reading a scene's and a tool's description back (ent_scene_read_desc, ent_tool_read_desc):
// a C description reads back field for field, a JSON scene as the C description of the same
// scene (which makes the same trajectory, bit for bit), a tool as it was added with its
// quaternion normalised; an older struct_size is served without writing past it. Every
// field of ent_scene_desc and ent_tool_desc goes through the scene's table both ways here,
// so a field the C binding (lib/capi/scene_desc.cpp, tools_api.cpp) misses fails.
#include "capi_test_support.h"

#include <cstddef>
#include <cstring>
#include <string>

using namespace capi_test;

namespace {

// The first byte at which two structs differ, or -1.
template <class T>
long first_difference(const T& a, const T& b) {
    const auto* x = reinterpret_cast<const unsigned char*>(&a);
    const auto* y = reinterpret_cast<const unsigned char*>(&b);
    for (std::size_t i = 0; i < sizeof(T); ++i)
        if (x[i] != y[i]) return static_cast<long>(i);
    return -1;
}

ent_scene_desc read_desc(const ent_scene* scene) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    EXPECT_EQ(ent_scene_read_desc(scene, &desc), ENT_OK) << ent_last_error();
    return desc;
}

ent_tool_desc read_tool(const ent_scene* scene, int32_t tool) {
    ent_tool_desc desc;
    ent_tool_desc_default(&desc);
    EXPECT_EQ(ent_tool_read_desc(scene, tool, &desc), ENT_OK) << ent_last_error();
    return desc;
}

// Every field of the description away from its default (and each valid).
ent_scene_desc every_field_changed() {
    ent_scene_desc d = default_desc();
    d.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_PINNED) |
                ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    d.length_m = 1.25;
    d.radius_m = 0.011;
    d.control_points = 31;
    d.linear_density_kg_per_m = 0.35;
    d.stretch_stiffness_N = 90.0;
    d.bend_stiffness_N_m2 = 3e-3;
    d.shape = ENT_SHAPE_SERPENTINE;
    d.shape_center_m[0] = 0.01, d.shape_center_m[1] = 0.02, d.shape_center_m[2] = 0.03;
    d.shape_direction[0] = 0.0, d.shape_direction[1] = 1.0, d.shape_direction[2] = 0.5;
    d.shape_leg_length_m = 0.2;
    d.shape_leg_spacing_m = 0.03;
    d.shape_helix_radius_m = 0.12;
    d.shape_helix_pitch_m = 0.04;
    d.integrator = ENT_INTEGRATOR_BDF2;
    d.timestep_s = 5e-4;
    d.max_substeps = 500;
    d.max_subdivisions = 5;
    d.max_speed_m_per_s = 40.0;
    d.gravity_m_per_s2[0] = 0.1, d.gravity_m_per_s2[1] = -0.2, d.gravity_m_per_s2[2] = -9.7;
    d.drag_N_s_per_m2 = 0.06;
    d.stretch_damping_N_s = 0.04;
    d.bend_damping_N_m2_s = 1e-4;
    d.mesentery_root_start_m[0] = -0.05, d.mesentery_root_start_m[2] = 0.01;
    d.mesentery_root_end_m[0] = 0.05, d.mesentery_root_end_m[2] = 0.02;
    d.mesentery_attachments = 10;
    d.mesentery_stiffness_N_per_m = 4.0;
    d.mesentery_rest_length_m = 0.01;
    d.pinned_ends = ENT_PIN_FIRST;
    d.collision_sphere_spacing_m = 0.005;
    d.contact_stiffness_N_per_m = 450.0;
    d.contact_damping_N_s_per_m = 0.4;
    d.contact_friction = 0.25;
    d.contact_slip_speed_m_per_s = 0.02;
    d.clamped_ends = ENT_PIN_LAST;
    return d;
}

TEST(ReadDesc, ACDescriptionReadsBackFieldForField) {
    const ent_scene_desc given = every_field_changed();
    const ScenePtr scene = create(given);
    ASSERT_TRUE(scene);
    const ent_scene_desc back = read_desc(scene.get());
    EXPECT_EQ(first_difference(back, given), -1) << "ent_scene_desc differs at byte " << first_difference(back, given);
    EXPECT_EQ(back.radius_m, 0.011);
    EXPECT_EQ(back.clamped_ends, ENT_PIN_LAST);
}

TEST(ReadDesc, AnEffectLeftOffReadsBackWithItsBitClearAndItsDefaults) {
    ent_scene_desc given = every_field_changed();
    given.effects &= ~(ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY));
    const ScenePtr scene = create(given);
    ASSERT_TRUE(scene);
    const ent_scene_desc back = read_desc(scene.get());
    const ent_scene_desc defaults = default_desc();
    EXPECT_EQ(back.effects, given.effects);
    EXPECT_EQ(back.mesentery_stiffness_N_per_m, defaults.mesentery_stiffness_N_per_m);
    EXPECT_EQ(back.gravity_m_per_s2[2], defaults.gravity_m_per_s2[2]);
    EXPECT_EQ(back.drag_N_s_per_m2, given.drag_N_s_per_m2);
}

TEST(ReadDesc, TheJsonOfTheDefaultDescriptionReadsBackAsIt) {
    const ScenePtr scene = create_json(R"({"gravity": [0, 0, -9.81], "damping": {}})");
    ASSERT_TRUE(scene);
    const ent_scene_desc back = read_desc(scene.get());
    const ent_scene_desc defaults = default_desc();
    EXPECT_EQ(first_difference(back, defaults), -1) << "differs at byte " << first_difference(back, defaults);
}

TEST(ReadDesc, AJsonSceneReadBackIsTheSameSceneInC) {
    const ScenePtr json = create_json(R"({
        "intestine": {"length": 1.2, "radius": 0.011, "control_points": 30, "linear_density": 0.35,
                      "bend_stiffness": 0.003,
                      "shape": {"kind": "serpentine", "center": [0, 0, 0.05], "leg_length": 0.2, "leg_spacing": 0.03}},
        "solver": {"integrator": "bdf2", "timestep": 0.0005, "max_speed": 40},
        "gravity": [0, 0, -9.81],
        "damping": {"drag": 0.07},
        "mesentery": {"root": [[-0.05, 0, 0.1], [0.05, 0, 0.12]], "attachments": 8, "stiffness": 3},
        "pinned": {"ends": "first", "clamped": "last"},
        "collision": {"stiffness": 400, "sphere_spacing": 0.006},
        "self_collision": {}})");
    ASSERT_TRUE(json);
    const ent_scene_desc back = read_desc(json.get());
    EXPECT_EQ(back.length_m, 1.2);
    EXPECT_EQ(back.integrator, ENT_INTEGRATOR_BDF2);
    EXPECT_EQ(back.mesentery_root_end_m[2], 0.12);
    EXPECT_EQ(back.clamped_ends, ENT_PIN_LAST);
    EXPECT_EQ(back.collision_sphere_spacing_m, 0.006);
    EXPECT_NE(back.effects & ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION), 0u);
    EXPECT_EQ(back.effects & ENT_EFFECT_BIT(ENT_EFFECT_ENVIRONMENT), 0u);
    const ScenePtr c = create(back);
    ASSERT_TRUE(c);
    for (int i = 0; i < 50; ++i) {
        ASSERT_EQ(ent_scene_step(json.get(), 1e-3), ENT_OK) << ent_last_error();
        ASSERT_EQ(ent_scene_step(c.get(), 1e-3), ENT_OK) << ent_last_error();
    }
    EXPECT_EQ(control_points(json.get()), control_points(c.get())) << "the same scene, bit for bit";
}

TEST(ReadDesc, TheArraysAreNotKept) {
    std::vector<double> points;
    for (int i = 0; i < 8; ++i) points.insert(points.end(), {0.05 * i, 0.0, 0.0});
    const uint32_t pins[] = {3};
    ent_scene_desc given = default_desc();
    given.control_points = 8;
    given.length_m = 0.35;
    given.shape = ENT_SHAPE_POINTS;
    given.shape_points_xyz_m = points.data();
    given.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    given.pinned_points = pins;
    given.pinned_point_count = 1;
    const ScenePtr scene = create(given);
    ASSERT_TRUE(scene);
    const ent_scene_desc back = read_desc(scene.get());
    EXPECT_EQ(back.shape, ENT_SHAPE_POINTS);
    EXPECT_EQ(back.shape_points_xyz_m, nullptr);
    EXPECT_EQ(back.pinned_points, nullptr);
    EXPECT_EQ(back.pinned_point_count, 0u);
    EXPECT_EQ(back.callbacks, nullptr);
}

TEST(ReadDesc, AnOlderStructIsNotWrittenPastItsSize) {
    const ScenePtr scene = create(every_field_changed());
    ASSERT_TRUE(scene);
    ent_scene_desc older;
    std::memset(&older, 0x5a, sizeof older);
    older.struct_size = static_cast<uint32_t>(offsetof(ent_scene_desc, clamped_ends));
    ASSERT_EQ(ent_scene_read_desc(scene.get(), &older), ENT_OK) << ent_last_error();
    EXPECT_EQ(older.radius_m, 0.011);
    int32_t untouched;
    std::memset(&untouched, 0x5a, sizeof untouched);
    EXPECT_EQ(older.clamped_ends, untouched);
}

TEST(ReadDesc, AToolReadsBackAsAddedItsQuaternionNormalised) {
    const ScenePtr scene = create_json(R"({"tools": [
        {"radius": 0.004, "length": 0.25, "max_force": 3, "grasp_margin": 0.002, "grasp_stiffness": 150,
         "grasp_damping": 1.5, "position": [0.3, 0.0, 0.4], "orientation": [2, 0, 0, 0], "mode": "direct",
         "coupling_stiffness": 800, "coupling_damping": 0.5, "friction": 0.2, "passivity_limiter": true,
         "jaw_length": 0.02, "jaw_opening": 0.015},
        {}]})");
    ASSERT_TRUE(scene);
    const ent_tool_desc first = read_tool(scene.get(), 0);
    EXPECT_EQ(first.radius_m, 0.004);
    EXPECT_EQ(first.length_m, 0.25);
    EXPECT_EQ(first.max_force_N, 3.0);
    EXPECT_EQ(first.grasp_margin_m, 0.002);
    EXPECT_EQ(first.grasp_stiffness_N_per_m, 150.0);
    EXPECT_EQ(first.grasp_damping_N_s_per_m, 1.5);
    EXPECT_EQ(first.position_m[0], 0.3);
    EXPECT_EQ(first.position_m[2], 0.4);
    EXPECT_EQ(first.orientation_wxyz[0], 1.0);
    EXPECT_EQ(first.mode, ENT_TOOL_MODE_DIRECT);
    EXPECT_EQ(first.coupling_stiffness_N_per_m, 800.0);
    EXPECT_EQ(first.coupling_damping_N_s_per_m, 0.5);
    EXPECT_EQ(first.friction, 0.2);
    EXPECT_EQ(first.passivity_limiter, 1);
    EXPECT_EQ(first.jaw_length_m, 0.02);
    EXPECT_EQ(first.jaw_opening_m, 0.015);

    ent_tool_desc defaults;
    ent_tool_desc_default(&defaults);
    const ent_tool_desc second = read_tool(scene.get(), 1);
    EXPECT_EQ(first_difference(second, defaults), -1) << "differs at byte " << first_difference(second, defaults);

    // What ent_tool_add takes reads back the same, as a new tool.
    int32_t copy = -1;
    ASSERT_EQ(ent_tool_add(scene.get(), &first, &copy), ENT_OK) << ent_last_error();
    const ent_tool_desc again = read_tool(scene.get(), copy);
    EXPECT_EQ(first_difference(again, first), -1) << "differs at byte " << first_difference(again, first);

    // A removed tool has no description any more.
    ASSERT_EQ(ent_tool_remove(scene.get(), 0), ENT_OK);
    ent_tool_desc removed = defaults;
    EXPECT_EQ(ent_tool_read_desc(scene.get(), 0, &removed), ENT_ERROR_NOT_FOUND);
    EXPECT_NE(std::string(ent_last_error()).find("removed"), std::string::npos) << ent_last_error();
    EXPECT_EQ(first_difference(removed, defaults), -1) << "written on failure";
}

TEST(ReadDesc, AnOlderToolStructIsNotWrittenPastItsSize) {
    const ScenePtr scene = create_json(R"({"tools": [{"radius": 0.004, "mode": "direct"}]})");
    ASSERT_TRUE(scene);
    ent_tool_desc older;
    std::memset(&older, 0x5a, sizeof older);
    older.struct_size = static_cast<uint32_t>(offsetof(ent_tool_desc, mode));
    ASSERT_EQ(ent_tool_read_desc(scene.get(), 0, &older), ENT_OK) << ent_last_error();
    EXPECT_EQ(older.radius_m, 0.004);
    int32_t untouched;
    std::memset(&untouched, 0x5a, sizeof untouched);
    EXPECT_EQ(older.mode, untouched);
}

}  // namespace
