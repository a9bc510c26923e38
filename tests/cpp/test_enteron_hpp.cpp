// SPDX-License-Identifier: Apache-2.0
// The C++ layer (include/enteron/enteron.hpp), built twice: as C++17 without Eigen and as
// C++20 with <Eigen/Core> included first (ENTERON_HPP_TEST_EIGEN), both with -Wall -Wextra
// -Werror -pedantic. Each test checks the wrapper against the C call it wraps.
#ifdef ENTERON_HPP_TEST_EIGEN
#include <Eigen/Core>
#endif
#include <enteron/enteron.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

static_assert(!std::is_copy_constructible_v<enteron::Scene> && std::is_nothrow_move_constructible_v<enteron::Scene>);
static_assert(!std::is_copy_constructible_v<enteron::Skin> && std::is_nothrow_move_constructible_v<enteron::Skin>);
static_assert(!std::is_copy_constructible_v<enteron::Tool> && std::is_nothrow_move_constructible_v<enteron::Tool>);

enteron::Scene small_scene() {
    enteron::SceneDesc desc;
    desc.length_m = 0.4;
    desc.control_points = 17;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_center_m[0] = -0.2;
    desc.shape_center_m[2] = 0.0125;
    return enteron::Scene(desc);
}

TEST(CppLayer, DescsHoldTheLibrarysDefaults) {
    ent_scene_desc c;
    ent_scene_desc_default(&c);
    const enteron::SceneDesc cpp;
    EXPECT_EQ(std::memcmp(&c, static_cast<const ent_scene_desc*>(&cpp), sizeof c), 0);
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    EXPECT_EQ(enteron::ToolDesc().max_force_N, tool.max_force_N);
    EXPECT_EQ(enteron::SkinDesc().struct_size, sizeof(ent_skin_desc));
    EXPECT_EQ(enteron::ObstacleDesc().struct_size, sizeof(ent_obstacle_desc));
}

// Issue 27, defect 3: an array and its count come from one container, so the library never
// reads past an array whose count says more than it holds.
TEST(CppLayer, ArraysSetTheirCountsThemselves) {
    const std::vector<double> xyz = {0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.2, 0.0, 0.0, 0.3, 0.0, 0.0, 0.4, 0.0, 0.0};
    const std::vector<uint32_t> held = {0, 4};
    enteron::SceneDesc desc;
    desc.shape_points(xyz).pinned(held);
    EXPECT_EQ(desc.control_points, 5u);
    EXPECT_EQ(desc.shape, ENT_SHAPE_POINTS);
    EXPECT_EQ(desc.shape_points_xyz_m, xyz.data());
    EXPECT_EQ(desc.pinned_point_count, 2u);
    EXPECT_NE(desc.effects & ENT_EFFECT_BIT(ENT_EFFECT_PINNED), 0u);
    const enteron::Scene scene(desc);
    EXPECT_EQ(scene.control_points(), xyz);
    try {
        desc.shape_points(std::vector<double>(7, 0.0));
        ADD_FAILURE() << "7 values taken as points";
    } catch (const enteron::Error& error) {
        EXPECT_EQ(error.status(), ENT_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(error.what()).find("shape_points_xyz_m"), std::string::npos) << error.what();
    }
    EXPECT_EQ(desc.control_points, 5u);  // a refused array changes nothing
    const double box[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const uint32_t faces[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    enteron::ObstacleDesc organ;
    organ.mesh(box, faces);
    EXPECT_EQ(organ.mesh_vertex_count, 4u);
    EXPECT_EQ(organ.mesh_triangle_count, 4u);
    EXPECT_EQ(organ.kind, ENT_OBSTACLE_MESH);
}

TEST(CppLayer, AFailingCallThrowsTheLibrarysMessage) {
    enteron::SceneDesc desc;
    desc.length_m = -1.0;
    try {
        enteron::Scene scene(desc);
        FAIL() << "a negative length was accepted";
    } catch (const enteron::Error& error) {
        EXPECT_EQ(error.status(), ENT_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(error.what()).find("length_m"), std::string::npos) << error.what();
    }
    EXPECT_THROW(enteron::Scene::from_json("{not json"), enteron::Error);
    enteron::Scene scene = small_scene();
    EXPECT_THROW(scene.step(-1.0), enteron::Error);
    EXPECT_THROW(scene.tool(3), enteron::Error) << "no tool 3";
}

TEST(CppLayer, HandlesMoveAndOwnTheirObject) {
    enteron::Scene a = small_scene();
    ent_scene* raw = a.get();
    enteron::Scene b = std::move(a);
    EXPECT_EQ(a.get(), nullptr);
    EXPECT_EQ(b.get(), raw);
    b.step(1e-3);
    EXPECT_EQ(b.stats().steps, 1u);
    enteron::Scene c = small_scene();
    c = std::move(b);  // c's own scene is destroyed here (ASan would see a leak otherwise)
    EXPECT_EQ(c.get(), raw);
    ent_scene* released = c.release();
    EXPECT_EQ(c.get(), nullptr);
    enteron::Scene d(released);  // owned again
    EXPECT_EQ(d.stats().steps, 1u);
}

TEST(CppLayer, QueriesMatchTheCApi) {
    enteron::Scene scene = small_scene();
    scene.step(1e-3);
    const std::vector<double> q = scene.control_points();
    ASSERT_EQ(q.size(), 3u * 17);
    std::vector<double> c(q.size());
    uint32_t count = 0;
    ASSERT_EQ(ent_scene_control_points(scene.get(), 17, c.data(), &count), ENT_OK);
    EXPECT_EQ(q, c);
    const std::vector<double> axis = scene.axis(50);
    EXPECT_EQ(axis.size(), 150u);
    EXPECT_NEAR(axis[0], q[0], 1e-12);
    EXPECT_EQ(scene.effect_stats(ENT_EFFECT_STRETCH).enabled, 1);
#ifdef ENTERON_HPP_TEST_EIGEN
    const auto points = enteron::as_matrix(q);
    EXPECT_EQ(points.rows(), 17);
    EXPECT_EQ(points(16, 0), q[3 * 16]);
    EXPECT_EQ(points.row(5).y(), q[3 * 5 + 1]);
#endif
}

TEST(CppLayer, ToolsContactsAndSaveRestore) {
    enteron::Scene scene = small_scene();
    enteron::ObstacleDesc floor;
    floor.kind = ENT_OBSTACLE_PLANE;
    EXPECT_EQ(scene.add_obstacle(floor), 0);
    enteron::ToolDesc desc;
    desc.position_m[1] = 0.05;
    desc.position_m[2] = 0.0125;
    enteron::Tool tool = scene.add_tool(desc);
    const double identity[4] = {1, 0, 0, 0};
    std::vector<unsigned char> saved;
    for (int i = 1; i <= 400; ++i) {
        const double tip[3] = {0.0, 0.05 - 1e-4 * i, 0.0125};
        tool.set_pose(tip, identity);
        scene.step(1e-3);
        if (i == 200) saved = scene.save_state();
    }
    const ent_tool_feedback feedback = tool.feedback();
    EXPECT_GT(feedback.contacts, 0u) << "the tool pushes the bowel";
    std::vector<double> ranges;
    const ent_tool_contacts touched = tool.contacts(&ranges);
    EXPECT_EQ(touched.contacts, feedback.contacts);
    EXPECT_EQ(ranges.size(), 2u * touched.range_count);
    EXPECT_EQ(touched.ranges_u, nullptr) << "no pointer into a vector the caller may free";
    double sum = 0.0;
    for (const ent_contact& c : scene.contacts())
        if (c.kind == ENT_CONTACT_TOOL) sum += c.force_N[1];
    EXPECT_NEAR(sum, -feedback.force_N[1], 1e-12);
    EXPECT_EQ(scene.contact_summary().tool_contacts, feedback.contacts);
    // A push of well under max_force (5 N) is not saturated (issue 27: ent_tool_feedback.saturated).
    EXPECT_LT(std::sqrt(feedback.force_N[0] * feedback.force_N[0] + feedback.force_N[1] * feedback.force_N[1] +
                        feedback.force_N[2] * feedback.force_N[2]),
              1.0);
    EXPECT_EQ(feedback.saturated, 0);

    const std::vector<double> at_400 = scene.control_points();
    scene.restore_state(saved);
    EXPECT_EQ(scene.stats().steps, 200u);
    for (int i = 201; i <= 400; ++i) {
        const double tip[3] = {0.0, 0.05 - 1e-4 * i, 0.0125};
        tool.set_pose(tip, identity);
        scene.step(1e-3);
    }
    EXPECT_EQ(scene.control_points(), at_400) << "bit-identical after the restore";
    saved[saved.size() / 2] ^= 1;
    try {
        scene.restore_state(saved);
        FAIL() << "a changed state was accepted";
    } catch (const enteron::Error& error) {
        EXPECT_EQ(error.status(), ENT_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(error.what()).find("checksum"), std::string::npos) << error.what();
    }
    EXPECT_EQ(scene.control_points(), at_400);
}

TEST(CppLayer, VersionEffectNamesAndCallbacks) {
    EXPECT_EQ(enteron::version(), ent_version());
    EXPECT_TRUE(enteron::compatible_version());
    EXPECT_EQ(enteron::effect_name(ENT_EFFECT_GRAVITY), "gravity");
    EXPECT_TRUE(enteron::effect_name(99).empty());
    ent_callbacks c;
    ent_callbacks_default(&c);
    const enteron::Callbacks cpp;
    EXPECT_EQ(std::memcmp(&c, static_cast<const ent_callbacks*>(&cpp), sizeof c), 0);
    // A scene made with hooks logs through them: here a warning about a bowel far too long.
    enteron::Callbacks logging;
    std::string log;
    logging.user_data = &log;
    logging.log = [](void* user, int32_t, const char* message) { static_cast<std::string*>(user)->append(message); };
    const enteron::Scene scene = enteron::Scene::from_json(R"({"intestine": {"length": 60, "control_points": 12}})", logging);
    EXPECT_NE(log.find("intestine.length"), std::string::npos) << log;
}

TEST(CppLayer, ASceneFileAndItsMeshFiles) {
    // Files of their own for the C++17 and the C++20 build, which ctest may run at once.
    const std::string directory = ::testing::TempDir() + "enteron_cpp" + std::to_string(__cplusplus);
    ASSERT_EQ(std::system(("mkdir -p " + directory).c_str()), 0);
    const std::string mesh_path = directory + "/organ.obj", scene_path = directory + "/scene.json";
    std::ofstream(mesh_path) << "v 0 0 -0.1\nv 1 0 -0.1\nv 0 1 -0.1\nf 1 2 3\n";
    std::ofstream(scene_path) << R"({"intestine": {"length": 0.3, "control_points": 12, "shape": {"kind": "line"}},
                                     "environment": [{"type": "mesh", "file": "organ.obj"}]})";
    enteron::Scene scene = enteron::Scene::from_json_file(scene_path);
    EXPECT_EQ(scene.obstacle_count(), 1u);
    const enteron::ObstacleMesh mesh = scene.obstacle_mesh(0);
    EXPECT_EQ(mesh.vertex_count(), 3u);
    EXPECT_EQ(mesh.triangles, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(mesh.vertices_xyz_m[3], 1.0);
    std::ofstream(mesh_path) << "v 0 0 0\nf 1 2 3\n";  // a face past the last vertex
    try {
        enteron::Scene::from_json_file(scene_path);
        FAIL() << "a broken mesh file was read";
    } catch (const enteron::Error& error) {
        EXPECT_EQ(error.status(), ENT_ERROR_INVALID_SCENE);
        EXPECT_NE(std::string(error.what()).find("line 2: a face refers to vertex 3"), std::string::npos) << error.what();
    }
    std::remove(mesh_path.c_str());
    std::remove(scene_path.c_str());
}

TEST(CppLayer, ObstaclesMoveTurnSlipAndGo) {
    enteron::Scene scene = small_scene();
    enteron::ObstacleDesc floor;
    floor.kind = ENT_OBSTACLE_PLANE;
    enteron::ObstacleDesc ball;
    ball.kind = ENT_OBSTACLE_SPHERE;
    ball.radius_m = 0.02;
    ball.center_m[2] = -0.5;
    const int32_t plane = scene.add_obstacle(floor), sphere = scene.add_obstacle(ball);
    EXPECT_EQ(scene.obstacle_count(), 2u);
    enteron::Pose lowered;
    lowered.position_m = {0.0, 0.0, -0.01};
    scene.set_obstacle_pose(plane, lowered);
    const double linear[3] = {0.0, 0.0, -10.0}, angular[3] = {0.0, 0.0, 0.0};
    scene.set_obstacle_velocity(plane, linear, angular);
    scene.set_obstacle_friction(plane, 0.0);
    scene.step(1e-3);
    const enteron::Pose pose = scene.obstacle_pose(plane);
    double c_position[3], c_orientation[4];
    ASSERT_EQ(ent_obstacle_pose(scene.get(), plane, c_position, c_orientation), ENT_OK);
    EXPECT_EQ(pose.position_m[2], c_position[2]);
    EXPECT_EQ(pose.position_m[2], -0.01) << "it reached the pose at the end of the step";
    EXPECT_EQ(pose.orientation_wxyz[0], c_orientation[0]);
    scene.remove_obstacle(sphere);
    EXPECT_EQ(scene.obstacle_count(), 1u);
    try {
        scene.obstacle_pose(sphere);
        FAIL() << "a removed obstacle has a pose";
    } catch (const enteron::Error& error) {
        EXPECT_EQ(error.status(), ENT_ERROR_NOT_FOUND);
    }
    EXPECT_THROW(scene.obstacle_mesh(plane), enteron::Error) << "a plane is not a mesh";
}

TEST(CppLayer, GravityPinsAndAttachments) {
    enteron::SceneDesc desc;
    desc.length_m = 0.4;
    desc.control_points = 17;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_center_m[0] = -0.2;
    desc.clamped_ends = ENT_PIN_FIRST;  // (with the effect "pinned")
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    enteron::Scene scene(desc);
    const double no_gravity[3] = {0.0, 0.0, 0.0};
    scene.set_gravity(no_gravity);
    scene.pin_point(16);
    for (int i = 0; i < 50; ++i) scene.step(1e-3);
    const std::vector<double> before = scene.control_points();
    EXPECT_LT(scene.stats().kinetic_energy_J, 1e-20) << "no gravity, pinned and clamped ends: at rest";
    const double down[3] = {0.0, 0.0, -9.81};
    scene.set_gravity(down);
    scene.step(1e-3);
    EXPECT_EQ(scene.control_points()[3 * 16 + 2], before[3 * 16 + 2]) << "the pinned point stays";
    EXPECT_LT(scene.control_points()[3 * 8 + 2], before[3 * 8 + 2]) << "the middle falls";
    scene.unpin_point(16);
    EXPECT_THROW(scene.unpin_point(16), enteron::Error) << "not pinned any more";
    enteron::ObstacleDesc organ;
    organ.kind = ENT_OBSTACLE_SPHERE;
    organ.center_m[2] = -1.0;
    const int32_t id = scene.add_obstacle(organ);
    scene.attach_mesentery(id);
    scene.attach_clamped_end(ENT_PIN_FIRST, id);
    scene.pin_point(10, id);
    try {
        scene.attach_clamped_end(ENT_PIN_LAST, id);
        FAIL() << "the last end is not clamped";
    } catch (const enteron::Error& error) {
        EXPECT_EQ(error.status(), ENT_ERROR_NOT_FOUND);
    }
    scene.step(1e-3);
}

TEST(CppLayer, ToolsReportWrenchStiffnessAndStatsAndCanBeRemoved) {
    enteron::Scene scene = small_scene();
    enteron::ObstacleDesc floor;
    floor.kind = ENT_OBSTACLE_PLANE;
    scene.add_obstacle(floor);
    enteron::ToolDesc desc;
    desc.position_m[2] = 2 * 0.0125 + 0.004;
    enteron::Tool tool = scene.add_tool(desc);
    enteron::Tool other = scene.add_tool(desc);
    EXPECT_EQ(scene.tool_count(), 2);
    // What they were made from reads back (ent_tool_read_desc, ent_scene_read_desc).
    EXPECT_EQ(tool.desc().position_m[2], desc.position_m[2]);
    EXPECT_EQ(tool.desc().max_force_N, desc.max_force_N);
    EXPECT_EQ(scene.desc().control_points, 17u);
    EXPECT_EQ(scene.desc().length_m, 0.4);
    const double identity[4] = {1, 0, 0, 0};
    for (int i = 1; i <= 100; ++i) {
        const double tip[3] = {0.0, 0.0, 2 * 0.0125 + 0.004 - 1e-4 * i};
        tool.set_pose(tip, identity);
        scene.step(1e-3);
    }
    const enteron::Wrench wrench = tool.wrench();
    double force[3], torque[3];
    ASSERT_EQ(ent_tool_wrench(scene.get(), tool.id(), force, torque), ENT_OK);
    EXPECT_EQ(wrench.force_N[2], force[2]);
    EXPECT_GT(wrench.force_N[2], 0.0) << "the bowel pushes the tool up";
    double k[9];
    ASSERT_EQ(ent_tool_stiffness(scene.get(), tool.id(), k), ENT_OK);
    const std::array<double, 9> stiffness = tool.stiffness();
    EXPECT_TRUE(std::equal(stiffness.begin(), stiffness.end(), k));
    const ent_tool_stats stats = tool.stats();
    EXPECT_EQ(stats.steps, 100u);
    EXPECT_GT(stats.energy_in_J, 0.0);
    other.remove();
    EXPECT_EQ(scene.tool_count(), 1);
    EXPECT_THROW(other.wrench(), enteron::Error);
    EXPECT_THROW(other.remove(), enteron::Error) << "already removed";
}

TEST(CppLayer, TheFeedbackSaysWhenMaxForceBoundedTheForce) {
    enteron::Scene scene = small_scene();
    enteron::ObstacleDesc floor;
    floor.kind = ENT_OBSTACLE_PLANE;
    scene.add_obstacle(floor);
    enteron::ToolDesc desc;
    desc.max_force_N = 0.05;  // less than pushing the bowel aside takes
    desc.position_m[1] = 0.05;
    desc.position_m[2] = 0.0125;
    enteron::Tool tool = scene.add_tool(desc);
    const double identity[4] = {1, 0, 0, 0};
    for (int i = 1; i <= 400; ++i) {
        const double tip[3] = {0.0, 0.05 - 1e-4 * i, 0.0125};
        tool.set_pose(tip, identity);
        scene.step(1e-3);
    }
    const ent_tool_feedback feedback = tool.feedback();
    EXPECT_EQ(feedback.saturated, 1);
    EXPECT_NEAR(std::sqrt(feedback.force_N[0] * feedback.force_N[0] + feedback.force_N[1] * feedback.force_N[1] +
                          feedback.force_N[2] * feedback.force_N[2]),
                0.05, 1e-9);
}

TEST(CppLayer, SkinsGiveSpansOverTheMesh) {
    enteron::Scene scene = small_scene();
    enteron::SkinDesc desc;
    desc.method = ENT_SKIN_TUBE;
    enteron::Skin skin(scene, desc);
    EXPECT_EQ(skin.mesh().vertex_count(), 0u) << "empty before the first update";
    skin.update();
    const enteron::Mesh mesh = skin.mesh();
    ent_mesh_view view{};
    view.struct_size = sizeof view;
    ASSERT_EQ(ent_skin_mesh(skin.get(), &view), ENT_OK);
    EXPECT_EQ(mesh.vertex_count(), view.vertex_count);
    EXPECT_EQ(mesh.triangle_count(), view.triangle_count);
    EXPECT_EQ(mesh.positions_xyz_m.data(), view.positions_xyz_m);
    EXPECT_EQ(mesh.indices.size(), 3u * view.triangle_count);
    uint32_t largest = 0;
    for (const uint32_t index : mesh.indices) largest = std::max(largest, index);
    EXPECT_LT(largest, mesh.vertex_count());
    EXPECT_EQ(skin.metrics().watertight, 1);
#ifdef ENTERON_HPP_HAS_STD_SPAN
    const std::span<const float> normals = mesh.normals_xyz;
    EXPECT_EQ(normals.size(), 3 * mesh.vertex_count());
#endif
#ifdef ENTERON_HPP_TEST_EIGEN
    const auto normals_matrix = enteron::as_matrix(mesh.normals_xyz);
    EXPECT_NEAR(normals_matrix.row(7).norm(), 1.0, 1e-5);
    const auto triangles = enteron::as_matrix(mesh.indices);
    EXPECT_EQ(triangles.rows(), Eigen::Index(mesh.triangle_count()));
    EXPECT_EQ(triangles(2, 1), mesh.indices[7]);
#endif
    enteron::Skin moved = std::move(skin);
    EXPECT_EQ(skin.get(), nullptr);
    moved.update();
}

}  // namespace

TEST(CppLayer, AnExposureMeasuresWhatTheCApiMeasures) {
    enteron::Scene scene = small_scene();
    const auto axis = scene.axis(3);
    // One point right under the middle of the axis, one far beside it.
    const double points[6] = {axis[3], axis[4], axis[5] - 0.2, axis[3] + 0.5, axis[4] + 0.5, axis[5] - 0.2};
    enteron::ExposureDesc desc;
    desc.points_xyz_m = points;
    desc.point_count = 2;
    enteron::Exposure exposure(scene, desc, 4);
    const double eye[3] = {axis[3], axis[4], axis[5] + 0.3};
    const enteron::ExposureReport& report = exposure.measure(eye);
    EXPECT_DOUBLE_EQ(report.visible_fraction(), 0.5);
    ASSERT_EQ(report.element_visible.size(), 2u);
    EXPECT_EQ(report.element_visible[0], 0.0);
    EXPECT_EQ(report.element_visible[1], 1.0);
    EXPECT_EQ(report.spans(), 1u);
    EXPECT_EQ(report.spans_u.size(), 2u);
    EXPECT_LE(report.spans_u[0], 0.5);
    EXPECT_GE(report.spans_u[1], 0.5);
    enteron::Exposure moved = std::move(exposure);
    EXPECT_EQ(moved.measure(eye).result.samples, 2u);
    const double nan_eye[3] = {0.0, std::nan(""), 0.0};
    try {
        moved.measure(nan_eye);
        FAIL() << "a NaN viewpoint was accepted";
    } catch (const enteron::Error& error) {
        EXPECT_EQ(error.status(), ENT_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(error.what()).find("viewpoint_m[1]"), std::string::npos) << error.what();
    }
}
