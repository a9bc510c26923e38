// SPDX-License-Identifier: Apache-2.0
// Moving anatomy (issue 20): organ meshes against the analytic shapes they approximate,
// meshes that are open, non-manifold or bad, obstacles that move and jump, pins and the
// mesentery's root that follow an obstacle, and the run-time settings. Through the C API.
#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <utility>

#include "capi_test_support.h"
#include "test_meshes.h"

namespace {

using capi_test::max_abs_difference;
using capi_test::ScenePtr;

using test_meshes::box;
using test_meshes::capsule;
using test_meshes::icosphere;
using test_meshes::Mesh;

ent_obstacle_desc mesh_desc(const Mesh& m) {
    ent_obstacle_desc d;
    ent_obstacle_desc_default(&d);
    d.kind = ENT_OBSTACLE_MESH;
    d.mesh_vertices_xyz_m = m.vertices.data();
    d.mesh_vertex_count = uint32_t(m.vertices.size() / 3);
    d.mesh_triangles = m.triangles.data();
    d.mesh_triangle_count = uint32_t(m.triangles.size() / 3);
    return d;
}

// A straight bowel of `points` control points from `start` along x, no gravity, no
// self-contact: only what the obstacle does to it.
ScenePtr line_bowel(const double start[3], double length, uint32_t points, bool gravity = false) {
    ent_scene_desc desc = capi_test::default_desc();
    desc.length_m = length;
    desc.control_points = points;
    desc.shape = ENT_SHAPE_LINE;
    for (int k = 0; k < 3; ++k) desc.shape_center_m[k] = start[k];
    if (!gravity) desc.effects &= ~ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
    return capi_test::create(desc);
}

int32_t add(ent_scene* scene, const ent_obstacle_desc& desc) {
    int32_t id = -1;
    EXPECT_EQ(ent_scene_add_obstacle(scene, &desc, &id), ENT_OK) << ent_last_error();
    return id;
}

bool anatomy_step_n(ent_scene* scene, int steps, double dt = 1e-3) {
    for (int i = 0; i < steps; ++i)
        if (ent_scene_step(scene, dt) != ENT_OK) {
            ADD_FAILURE() << "step " << i << ": " << ent_last_error();
            return false;
        }
    return true;
}

// The same bowel against an analytic obstacle and the mesh that approximates it: contacts,
// penetration and motion agree within the field's error. `tolerance` is in metres: the
// mesh's own departure from the shape (its facets) plus the field's interpolation error.
void expect_same_as_analytic(const ent_obstacle_desc& analytic, const Mesh& mesh, const double start[3],
                             double tolerance) {
    ScenePtr a = line_bowel(start, 0.2, 20), m = line_bowel(start, 0.2, 20);
    ASSERT_TRUE(a && m);
    add(a.get(), analytic);
    add(m.get(), mesh_desc(mesh));
    ASSERT_TRUE(anatomy_step_n(a.get(), 1));
    ASSERT_TRUE(anatomy_step_n(m.get(), 1));
    const ent_stats sa = capi_test::stats(a.get()), sm = capi_test::stats(m.get());
    ASSERT_GT(sa.contacts, 0u) << "the test must touch the obstacle";
    EXPECT_NEAR(double(sm.contacts), double(sa.contacts), 2.0);
    EXPECT_NEAR(sm.max_penetration_m, sa.max_penetration_m, tolerance);
    // 30 ms later the contacts have pushed the bowel by millimetres: the same way.
    ASSERT_TRUE(anatomy_step_n(a.get(), 30));
    ASSERT_TRUE(anatomy_step_n(m.get(), 30));
    const std::vector<double> pa = capi_test::control_points(a.get()), pm = capi_test::control_points(m.get());
    const std::vector<double> p0 = capi_test::control_points(line_bowel(start, 0.2, 20).get());
    const double moved = max_abs_difference(pa, p0);
    EXPECT_GT(moved, 1e-4);
    EXPECT_LT(max_abs_difference(pa, pm), 0.1 * moved + tolerance) << "moved " << moved;
}

TEST(Anatomy, SphereMeshMatchesTheSphere) {
    const double c[3] = {0.0, 0.0, 0.0};
    ent_obstacle_desc sphere;
    ent_obstacle_desc_default(&sphere);
    sphere.kind = ENT_OBSTACLE_SPHERE;
    sphere.radius_m = 0.05;
    const double start[3] = {-0.1, 0.0, 0.05 + 0.0125 - 0.003};  // 3 mm into the top
    // Level 4: 5120 triangles, edges of 4 mm, facets at most 40 um inside the sphere.
    expect_same_as_analytic(sphere, icosphere(c, 0.05, 4), start, 1e-4);
}

TEST(Anatomy, CapsuleMeshMatchesTheCapsule) {
    ent_obstacle_desc analytic;
    ent_obstacle_desc_default(&analytic);
    analytic.kind = ENT_OBSTACLE_CAPSULE;
    analytic.radius_m = 0.03;
    analytic.start_m[2] = -0.05;
    analytic.end_m[2] = 0.05;
    const double start[3] = {-0.1, 0.0, 0.03 + 0.0125 - 0.003};  // along the top of its side, 3 mm in
    Mesh mesh = capsule(-0.05, 0.05, 0.03, 96);
    // The bowel runs along x across a capsule along z: swap so both lie the same way.
    analytic.start_m[2] = 0.0, analytic.end_m[2] = 0.0;
    analytic.start_m[1] = -0.05, analytic.end_m[1] = 0.05;
    for (std::size_t i = 0; i < mesh.vertices.size(); i += 3) std::swap(mesh.vertices[i + 1], mesh.vertices[i + 2]);
    for (std::size_t i = 0; i < mesh.triangles.size(); i += 3) std::swap(mesh.triangles[i + 1], mesh.triangles[i + 2]);
    expect_same_as_analytic(analytic, mesh, start, 1e-4);
}

TEST(Anatomy, InwardBoxMeshMatchesTheCavity) {
    const double c[3] = {0.0, 0.0, 0.0}, h[3] = {0.15, 0.1, 0.1};
    ent_obstacle_desc analytic;
    ent_obstacle_desc_default(&analytic);
    analytic.kind = ENT_OBSTACLE_BOX_INSIDE;
    for (int k = 0; k < 3; ++k) analytic.half_extents_m[k] = h[k];
    const double start[3] = {-0.1, 0.0, -0.1 + 0.0125 - 0.003};  // on the floor, 3 mm in
    expect_same_as_analytic(analytic, box(c, h, true), start, 1e-5);
}

// A log callback that keeps the warnings.
void keep_warnings(void* user, int32_t level, const char* message) {
    if (level >= ENT_LOG_WARNING) static_cast<std::string*>(user)->append(message).append("\n");
}

ScenePtr bowel_with_log(std::string* log, const double start[3], bool gravity) {
    ent_callbacks callbacks;
    ent_callbacks_default(&callbacks);
    callbacks.log = keep_warnings;
    callbacks.user_data = log;
    ent_scene_desc desc = capi_test::default_desc();
    desc.length_m = 0.3;
    desc.control_points = 24;
    desc.shape = ENT_SHAPE_LINE;
    for (int k = 0; k < 3; ++k) desc.shape_center_m[k] = start[k];
    if (!gravity) desc.effects &= ~ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
    desc.callbacks = &callbacks;
    return capi_test::create(desc);
}

TEST(Anatomy, AnOpenMeshHoldsTheBowelOnTheSideItsNormalsFace) {
    // A 40 cm square sheet at z = 0, normals up: no inside, so contact is one-sided.
    Mesh sheet{{-0.2, -0.2, 0.0, 0.2, -0.2, 0.0, 0.2, 0.2, 0.0, -0.2, 0.2, 0.0}, {0, 1, 2, 0, 2, 3}};
    std::string log;
    const double start[3] = {-0.15, 0.0, 0.03};
    ScenePtr scene = bowel_with_log(&log, start, true);
    ASSERT_TRUE(scene);
    add(scene.get(), mesh_desc(sheet));
    EXPECT_NE(log.find("one-sided"), std::string::npos) << log;
    ASSERT_TRUE(anatomy_step_n(scene.get(), 1000));
    const std::vector<double> p = capi_test::control_points(scene.get());
    for (std::size_t i = 2; i < p.size(); i += 3) EXPECT_GT(p[i], 0.0125 - 0.005) << "point " << i / 3 << " fell through";
}

TEST(Anatomy, ANonManifoldMeshIsAcceptedWithAWarningAndSteps) {
    // The sheet with a fin standing on its diagonal: that edge has three triangles. The fin
    // faces (1, -1, 0); the bowel lies along the diagonal on that side and a sideways
    // gravity slides it (frictionless) into the corner where fin and sheet meet.
    Mesh fin{{-0.2, -0.2, 0.0, 0.2, -0.2, 0.0, 0.2, 0.2, 0.0, -0.2, 0.2, 0.0, 0.0, 0.0, 0.1},
             {0, 1, 2, 0, 2, 3, 0, 2, 4}};
    std::string log;
    const double start[3] = {-0.09, -0.15, 0.0125};
    ent_callbacks callbacks;
    ent_callbacks_default(&callbacks);
    callbacks.log = keep_warnings;
    callbacks.user_data = &log;
    ent_scene_desc desc = capi_test::default_desc();
    desc.length_m = 0.2;
    desc.control_points = 16;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_direction[0] = desc.shape_direction[1] = std::sqrt(0.5), desc.shape_direction[2] = 0.0;
    for (int k = 0; k < 3; ++k) desc.shape_center_m[k] = start[k];
    desc.callbacks = &callbacks;
    ScenePtr scene = capi_test::create(desc);
    ASSERT_TRUE(scene);
    const int32_t id = add(scene.get(), mesh_desc(fin));
    EXPECT_NE(log.find("three or more"), std::string::npos) << log;
    ASSERT_EQ(ent_obstacle_set_friction(scene.get(), id, 0.0), ENT_OK);
    const double g[3] = {-3.0, 3.0, -9.81};
    ASSERT_EQ(ent_scene_set_gravity(scene.get(), g), ENT_OK);
    ASSERT_TRUE(anatomy_step_n(scene.get(), 1000));
    const std::vector<double> p = capi_test::control_points(scene.get());
    const double r = 0.0125;
    double closest = 1e9;
    for (std::size_t i = 0; i < p.size(); i += 3) {
        const double from_fin = (p[i] - p[i + 1]) / std::sqrt(2.0);
        closest = std::min(closest, from_fin);
        EXPECT_GT(p[i + 2], r - 0.005) << "point " << i / 3 << " sank into the sheet";
        EXPECT_GT(from_fin, r - 0.005) << "point " << i / 3 << " went through the fin";
    }
    EXPECT_LT(closest, r + 0.005) << "slid into the corner and rests against the fin";
}

// Every bad mesh is refused, named, and changes nothing.
TEST(Anatomy, BadMeshesAreRefusedAndChangeNothing) {
    const double start[3] = {-0.1, 0.0, 0.1};
    ScenePtr scene = line_bowel(start, 0.2, 20);
    ASSERT_TRUE(scene);
    const double c[3] = {0.0, 0.0, -0.2};
    const Mesh good = icosphere(c, 0.05, 1);
    uint32_t count = 0;
    auto expect_refused = [&](Mesh m, ent_obstacle_desc d, ent_status status, const char* words) {
        d.mesh_vertices_xyz_m = d.mesh_vertices_xyz_m == nullptr ? nullptr : m.vertices.data();
        if (d.mesh_triangles != nullptr) d.mesh_triangles = m.triangles.data();
        int32_t id = 77;
        EXPECT_EQ(ent_scene_add_obstacle(scene.get(), &d, &id), status) << words;
        EXPECT_NE(std::string(ent_last_error()).find(words), std::string::npos) << ent_last_error();
        EXPECT_EQ(id, 77);
        ASSERT_EQ(ent_scene_obstacle_count(scene.get(), &count), ENT_OK);
        EXPECT_EQ(count, 0u);
    };
    Mesh nan = good;
    nan.vertices[7] = std::nan("");
    expect_refused(nan, mesh_desc(nan), ENT_ERROR_INVALID_ARGUMENT, "vertices[2]");
    Mesh out_of_range = good;
    out_of_range.triangles[4] = 1000;
    expect_refused(out_of_range, mesh_desc(out_of_range), ENT_ERROR_INVALID_ARGUMENT, "triangles[1]");
    ent_obstacle_desc none = mesh_desc(good);
    none.mesh_triangle_count = 0;
    expect_refused(good, none, ENT_ERROR_INVALID_ARGUMENT, "at least one triangle");
    ent_obstacle_desc billion = mesh_desc(good);
    billion.mesh_triangle_count = 1000000000u;  // the arrays are far shorter: never read
    expect_refused(good, billion, ENT_ERROR_INVALID_ARGUMENT, "1000000000");
    ent_obstacle_desc no_array = mesh_desc(good);
    no_array.mesh_vertices_xyz_m = nullptr;
    expect_refused(good, no_array, ENT_ERROR_INVALID_ARGUMENT, "mesh_vertices_xyz_m");
    Mesh flat{{0, 0, 0, 1, 0, 0, 2, 0, 0}, {0, 1, 2}};
    expect_refused(flat, mesh_desc(flat), ENT_ERROR_INVALID_ARGUMENT, "zero area");
    ent_obstacle_desc huge_voxels = mesh_desc(good);
    huge_voxels.mesh_voxel_size_m = 1e-6;  // 10^14 voxels
    expect_refused(good, huge_voxels, ENT_ERROR_INVALID_ARGUMENT, "voxel size of at least");
    // And the good one goes in.
    add(scene.get(), mesh_desc(good));
    ASSERT_EQ(ent_scene_obstacle_count(scene.get(), &count), ENT_OK);
    EXPECT_EQ(count, 1u);
}

// A bowel lying on a floor, pushed by a vertical wall (a plane facing +x) moving at 5 cm/s:
// it is carried along, and its kinetic energy stays that of a bowel moving at the wall's
// speed (no energy from nothing).
TEST(Anatomy, AMovingPlateCarriesTheBowelWithoutEnergyFromNothing) {
    ent_scene_desc desc = capi_test::default_desc();
    desc.length_m = 0.3;
    desc.control_points = 24;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_direction[0] = 0.0, desc.shape_direction[1] = 1.0;  // along y, lying across the push
    desc.shape_center_m[0] = 0.02, desc.shape_center_m[1] = -0.15, desc.shape_center_m[2] = 0.0125;
    ScenePtr scene = capi_test::create(desc);
    ASSERT_TRUE(scene);
    ent_obstacle_desc floor;
    ent_obstacle_desc_default(&floor);
    floor.kind = ENT_OBSTACLE_PLANE;
    add(scene.get(), floor);
    ent_obstacle_desc wall;
    ent_obstacle_desc_default(&wall);
    wall.kind = ENT_OBSTACLE_PLANE;
    wall.normal[0] = 1.0, wall.normal[2] = 0.0;  // through the origin, bowel on +x
    const int32_t id = add(scene.get(), wall);
    const double speed = 0.05, q[4] = {1, 0, 0, 0};
    double largest_kinetic = 0.0;
    const double mass = 0.3 * 0.3;
    for (int i = 1; i <= 2000; ++i) {
        const double position[3] = {speed * 1e-3 * i, 0.0, 0.0};
        ASSERT_EQ(ent_obstacle_set_pose(scene.get(), id, position, q), ENT_OK) << ent_last_error();
        ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
        if (i > 200) largest_kinetic = std::max(largest_kinetic, capi_test::stats(scene.get()).kinetic_energy_J);
    }
    const std::vector<double> p = capi_test::control_points(scene.get());
    double min_x = 1e9;
    for (std::size_t i = 0; i < p.size(); i += 3) min_x = std::min(min_x, p[i]);
    // The wall is at x = 0.1 m: the bowel rests against it, R from it (a little deeper).
    EXPECT_GT(min_x, 0.1 + 0.0125 - 0.006);
    EXPECT_LT(min_x, 0.1 + 0.0125 + 0.01) << "carried along, not thrown ahead";
    EXPECT_LT(largest_kinetic, 4.0 * 0.5 * mass * speed * speed) << "moving at about the wall's speed";
}

// A sphere put into the middle of a resting bowel within one step is handled like a
// teleported tool: the step succeeds, the force is bounded, nothing explodes.
TEST(Anatomy, AnObstacleThatJumpsIsHandledWithBoundedForce) {
    const double start[3] = {-0.15, 0.0, 0.0125};
    ScenePtr scene = line_bowel(start, 0.3, 24, true);
    ASSERT_TRUE(scene);
    ent_obstacle_desc floor;
    ent_obstacle_desc_default(&floor);
    floor.kind = ENT_OBSTACLE_PLANE;
    add(scene.get(), floor);
    const double c[3] = {0.0, 0.0, 0.0};
    const Mesh ball = icosphere(c, 0.04, 3);
    ent_obstacle_desc organ = mesh_desc(ball);
    organ.position_m[2] = 0.3;  // 30 cm above
    const int32_t id = add(scene.get(), organ);
    ASSERT_TRUE(anatomy_step_n(scene.get(), 100));
    const double onto[3] = {0.0, 0.0, 0.03}, q[4] = {1, 0, 0, 0};
    ASSERT_EQ(ent_obstacle_set_pose(scene.get(), id, onto, q), ENT_OK);
    ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << ent_last_error();
    // k R per contact: at most 6.25 N on a sphere of 1.9 g for 1 ms, a few m/s.
    EXPECT_LT(capi_test::stats(scene.get()).kinetic_energy_J, 1.0);
    ASSERT_TRUE(anatomy_step_n(scene.get(), 500));
    for (double x : capi_test::control_points(scene.get())) EXPECT_TRUE(std::isfinite(x));
}

// A bowel end pinned to an organ follows it; released, it falls.
TEST(Anatomy, APinOnAnObstacleFollowsItAndCanBeReleased) {
    const double start[3] = {0.0, 0.0, 0.1};
    ScenePtr scene = line_bowel(start, 0.3, 24, true);
    ASSERT_TRUE(scene);
    ent_obstacle_desc organ;
    ent_obstacle_desc_default(&organ);
    organ.kind = ENT_OBSTACLE_SPHERE;
    organ.center_m[0] = -0.06, organ.center_m[2] = 0.1;
    organ.radius_m = 0.04;
    const int32_t id = add(scene.get(), organ);
    ASSERT_EQ(ent_scene_pin_point(scene.get(), 0, id), ENT_OK) << ent_last_error();
    const std::vector<double> before = capi_test::control_points(scene.get());
    const double q[4] = {1, 0, 0, 0};
    for (int i = 1; i <= 500; ++i) {  // up 5 cm in 0.5 s
        const double position[3] = {0.0, 0.0, 0.05 * i / 500.0};
        ASSERT_EQ(ent_obstacle_set_pose(scene.get(), id, position, q), ENT_OK);
        ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << ent_last_error();
    }
    std::vector<double> p = capi_test::control_points(scene.get());
    EXPECT_NEAR(p[0], before[0], 1e-6);
    EXPECT_NEAR(p[2], before[2] + 0.05, 1e-6);
    // A pin made at run time on a free point holds it where it is.
    const uint32_t middle = 12;
    ASSERT_TRUE(anatomy_step_n(scene.get(), 100));
    ASSERT_EQ(ent_scene_pin_point(scene.get(), middle, ENT_NO_OBSTACLE), ENT_OK) << ent_last_error();
    const std::vector<double> held = capi_test::control_points(scene.get());
    ASSERT_TRUE(anatomy_step_n(scene.get(), 200));
    p = capi_test::control_points(scene.get());
    for (int k = 0; k < 3; ++k) EXPECT_EQ(p[3 * middle + k], held[3 * middle + k]);
    // Released, the end falls with the rest.
    ASSERT_EQ(ent_scene_unpin_point(scene.get(), 0), ENT_OK);
    EXPECT_EQ(ent_scene_unpin_point(scene.get(), 0), ENT_ERROR_NOT_FOUND);
    ASSERT_TRUE(anatomy_step_n(scene.get(), 200));
    EXPECT_LT(capi_test::control_points(scene.get())[2], p[2] - 0.01);
}

// The mesentery's root on an organ: lifting the organ lifts the bowel that hangs from it.
TEST(Anatomy, TheMesenteryRootFollowsItsObstacle) {
    auto make = [](bool attach) {
        const std::string json = R"({"intestine": {"length": 0.6, "control_points": 24, "shape": {"kind": "line",
            "center": [-0.3, 0, 0]}}, "gravity": [0, 0, -9.81], "damping": {},
            "mesentery": {"root": [[-0.05, 0, 0.05], [0.05, 0, 0.05]], "stiffness": 20, "attachments": 12)" +
                                 std::string(attach ? R"(, "obstacle": 0)" : "") + R"(},
            "environment": [{"type": "sphere", "center": [0, 0, 0.2], "radius": 0.03}]})";
        return capi_test::create_json(json);
    };
    ScenePtr attached = make(true), free = make(false);
    ASSERT_TRUE(attached && free);
    const double q[4] = {1, 0, 0, 0};
    for (int i = 1; i <= 1000; ++i) {
        const double position[3] = {0.0, 0.0, 0.1 * std::min(1.0, i / 500.0)};
        for (ent_scene* s : {attached.get(), free.get()}) {
            ASSERT_EQ(ent_obstacle_set_pose(s, 0, position, q), ENT_OK);
            ASSERT_EQ(ent_scene_step(s, 1e-3), ENT_OK) << ent_last_error();
        }
    }
    auto mean_z = [](const std::vector<double>& p) {
        double z = 0.0;
        for (std::size_t i = 2; i < p.size(); i += 3) z += p[i];
        return z / double(p.size() / 3);
    };
    EXPECT_GT(mean_z(capi_test::control_points(attached.get())),
              mean_z(capi_test::control_points(free.get())) + 0.05);
}

// A clamped end on an obstacle's frame: a 40 cm bowel clamped at its first end, which rides
// on an organ that rises 3 cm and turns 40 degrees about z over 0.6 s, then rests.
std::string clamped_on_organ_json(const char* integrator, bool attached) {
    return std::string(R"({"intestine": {"length": 0.4, "control_points": 16, "shape": {"kind": "line",
        "center": [0, 0, 0], "direction": [1, 0, 0]}}, "gravity": [0, 0, -9.81], "damping": {},
        "solver": {"integrator": ")") +
           integrator + R"("}, "pinned": {"clamped": "first")" +
           (attached ? R"(, "clamped_attached": {"first": 0})" : "") + R"(},
        "environment": [{"type": "sphere", "position": [-0.05, 0.02, 0], "center": [0, 0, 0.3], "radius": 0.02}]})";
}

const double kOrganStart[3] = {-0.05, 0.02, 0.0};

// The organ's pose after `step` steps of 1 ms (smooth start and stop) and its turn about z.
void organ_pose(int step, double position[3], double orientation[4], double* angle) {
    const double s = std::min(1.0, step / 600.0), ramp = s * s * (3.0 - 2.0 * s);
    *angle = 40.0 * M_PI / 180.0 * ramp;
    const double p[3] = {kOrganStart[0], kOrganStart[1], kOrganStart[2] + 0.03 * ramp};
    const double q[4] = {std::cos(*angle / 2), 0.0, 0.0, std::sin(*angle / 2)};
    std::copy(p, p + 3, position);
    std::copy(q, q + 4, orientation);
}

std::array<double, 3> turned_about_z(double angle, const double v[3]) {
    return {std::cos(angle) * v[0] - std::sin(angle) * v[1], std::sin(angle) * v[0] + std::cos(angle) * v[1], v[2]};
}

// The direction of the first end's tangent, (4 q_1 - 3 q_0 - q_2) normalised.
std::array<double, 3> first_end_direction(const std::vector<double>& p) {
    std::array<double, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = 4.0 * p[3 + k] - 3.0 * p[k] - p[6 + k];
    const double norm = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    for (double& c : t) c /= norm;
    return t;
}

// Moves the organ for `steps` steps from step `from` (it rests after step 600).
void move_organ(ent_scene* scene, int from, int steps) {
    for (int i = from + 1; i <= from + steps; ++i) {
        double position[3], orientation[4], angle;
        organ_pose(i, position, orientation, &angle);
        ASSERT_EQ(ent_obstacle_set_pose(scene, 0, position, orientation), ENT_OK) << ent_last_error();
        ASSERT_EQ(ent_scene_step(scene, 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
    }
}

// The end point and the end's tangent follow the frame at every step, with every
// integrator: position to 1 um, direction to 1e-6 rad (the straight clamp of a free bowel
// turns too: checked against the unattached scene, whose end stays put). The bowel stays
// calm: no rollback, and its points move no faster than the organ's swing explains.
TEST(Anatomy, AClampedEndOnAnObstacleFollowsItsFrame) {
    for (const char* integrator : {"implicit_euler", "bdf2", "symplectic_euler", "rk4"}) {
        SCOPED_TRACE(integrator);
        ScenePtr scene = capi_test::create_json(clamped_on_organ_json(integrator, true));
        ScenePtr world = capi_test::create_json(clamped_on_organ_json(integrator, false));
        ASSERT_TRUE(scene && world);
        // Let it droop first, at rest.
        ASSERT_TRUE(anatomy_step_n(scene.get(), 500));
        ASSERT_TRUE(anatomy_step_n(world.get(), 500));
        const std::vector<double> start = capi_test::control_points(scene.get());
        const std::array<double, 3> start_direction = first_end_direction(start);
        const double local[3] = {start[0] - kOrganStart[0], start[1] - kOrganStart[1], start[2] - kOrganStart[2]};
        double worst_position = 0.0, worst_angle = 0.0, fastest = 0.0, fastest_still = 0.0;
        std::vector<double> before = start, before_still = capi_test::control_points(world.get());
        // The fastest control point between two positions 1 ms apart, m/s.
        const auto speed = [](const std::vector<double>& from, const std::vector<double>& to) {
            double most = 0.0;
            for (std::size_t c = 0; c + 2 < to.size(); c += 3) {
                const double dx = to[c] - from[c], dy = to[c + 1] - from[c + 1], dz = to[c + 2] - from[c + 2];
                most = std::max(most, std::sqrt(dx * dx + dy * dy + dz * dz) / 1e-3);
            }
            return most;
        };
        for (int i = 1; i <= 1000; ++i) {
            move_organ(scene.get(), i - 1, 1);
            ASSERT_EQ(ent_scene_step(world.get(), 1e-3), ENT_OK);
            const std::vector<double> still = capi_test::control_points(world.get());
            fastest_still = std::max(fastest_still, speed(before_still, still));
            before_still = still;
            double position[3], orientation[4], angle;
            organ_pose(i, position, orientation, &angle);
            const std::vector<double> p = capi_test::control_points(scene.get());
            const std::array<double, 3> end = turned_about_z(angle, local);
            for (int k = 0; k < 3; ++k) worst_position = std::max(worst_position, std::fabs(p[k] - (end[k] + position[k])));
            const std::array<double, 3> expected = turned_about_z(angle, start_direction.data());
            const std::array<double, 3> direction = first_end_direction(p);
            double dot = 0.0;
            for (int k = 0; k < 3; ++k) dot += direction[k] * expected[k];
            const double cross = std::sqrt(std::max(0.0, 1.0 - dot * dot));
            worst_angle = std::max(worst_angle, std::atan2(cross, dot));
            fastest = std::max(fastest, speed(before, p));
            before = p;
        }
        EXPECT_LT(worst_position, 1e-6);
        // BDF2's positions are not q + h v (the rate the clamp asks assumes that): it lags by
        // a few microradians, and the next step takes the lag back.
        EXPECT_LT(worst_angle, std::string(integrator) == "bdf2" ? 2e-5 : 1e-6);
        // The drooping bowel swings as the unattached one does, plus what the organ's turn
        // gives its tip (40 cm at 40 degrees in 0.6 s: about 1 m/s at most); an unstable
        // clamp would fling it far faster.
        EXPECT_LT(fastest, fastest_still + 1.0) << "the unattached bowel: " << fastest_still << " m/s";
        EXPECT_EQ(capi_test::stats(scene.get()).rollbacks, 0u);
        // The unattached clamp did not move.
        const std::vector<double> still = capi_test::control_points(world.get());
        for (int k = 0; k < 3; ++k) EXPECT_EQ(still[k], start[k]);
        // Its end turned with the organ: 40 degrees from the unattached scene's.
        const std::array<double, 3> w = first_end_direction(still), a = first_end_direction(before);
        EXPECT_NEAR(std::acos(std::min(1.0, w[0] * a[0] + w[1] * a[1] + w[2] * a[2])), 40.0 * M_PI / 180.0, 1e-3);
    }
}

// Attaching names a clamped end and an obstacle there is, or changes nothing.
TEST(Anatomy, AttachingAClampedEndRefusesBadInput) {
    ScenePtr scene = capi_test::create_json(clamped_on_organ_json("implicit_euler", false));
    ASSERT_TRUE(scene);
    EXPECT_EQ(ent_scene_attach_clamped_end(nullptr, ENT_PIN_FIRST, 0), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_scene_attach_clamped_end(scene.get(), 0, 0), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(ent_last_error()).find("ends"), std::string::npos) << ent_last_error();
    EXPECT_EQ(ent_scene_attach_clamped_end(scene.get(), ENT_PIN_LAST, 0), ENT_ERROR_NOT_FOUND);
    EXPECT_NE(std::string(ent_last_error()).find("last end is not clamped"), std::string::npos) << ent_last_error();
    EXPECT_EQ(ent_scene_attach_clamped_end(scene.get(), ENT_PIN_BOTH, 0), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_scene_attach_clamped_end(scene.get(), ENT_PIN_FIRST, 7), ENT_ERROR_NOT_FOUND);
    // Nothing changed: the organ moves, the end stays.
    const std::vector<double> start = capi_test::control_points(scene.get());
    move_organ(scene.get(), 0, 100);
    const std::vector<double> after = capi_test::control_points(scene.get());
    for (int k = 0; k < 3; ++k) EXPECT_EQ(after[k], start[k]);
    // Attached at run time, it follows; back in the world, it stays where it was left.
    ASSERT_EQ(ent_scene_attach_clamped_end(scene.get(), ENT_PIN_FIRST, 0), ENT_OK) << ent_last_error();
    move_organ(scene.get(), 100, 100);
    const std::vector<double> carried = capi_test::control_points(scene.get());
    EXPECT_GT(std::fabs(carried[2] - start[2]), 1e-3);
    ASSERT_EQ(ent_scene_attach_clamped_end(scene.get(), ENT_PIN_FIRST, ENT_NO_OBSTACLE), ENT_OK);
    move_organ(scene.get(), 200, 100);
    const std::vector<double> left = capi_test::control_points(scene.get());
    for (int k = 0; k < 3; ++k) EXPECT_EQ(left[k], carried[k]);

    // JSON: the end must be clamped, the obstacle must exist.
    ent_scene* bad = nullptr;
    const std::string unclamped = R"({"intestine": {"control_points": 16}, "pinned": {"clamped": "first",
        "clamped_attached": {"last": 0}}, "environment": [{"type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1]}]})";
    EXPECT_EQ(ent_scene_create_json(unclamped.data(), unclamped.size(), &bad), ENT_ERROR_INVALID_SCENE);
    EXPECT_NE(std::string(ent_last_error()).find("pinned.clamped_attached.last"), std::string::npos) << ent_last_error();
    std::string missing = clamped_on_organ_json("implicit_euler", true);
    missing.replace(missing.find(R"("first": 0)"), 10, R"("first": 3)");
    EXPECT_EQ(ent_scene_create_json(missing.data(), missing.size(), &bad), ENT_ERROR_INVALID_SCENE);
    EXPECT_NE(std::string(ent_last_error()).find("pinned.clamped_attached.first"), std::string::npos) << ent_last_error();
    // A clamped end's point pinned alone to an organ would leave the clamp half attached.
    const std::string end_point_pinned = R"({"intestine": {"control_points": 16}, "pinned": {"clamped": "last",
        "attached": [{"control_point": 15, "obstacle": 0}]},
        "environment": [{"type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1]}]})";
    EXPECT_EQ(ent_scene_create_json(end_point_pinned.data(), end_point_pinned.size(), &bad), ENT_ERROR_INVALID_SCENE);
    EXPECT_NE(std::string(ent_last_error()).find("pinned.attached[0].control_point"), std::string::npos)
        << ent_last_error();
    const std::string not_an_object = R"({"intestine": {"control_points": 16}, "pinned": {"clamped": "first",
        "clamped_attached": 0}})";
    EXPECT_EQ(ent_scene_create_json(not_an_object.data(), not_an_object.size(), &bad), ENT_ERROR_INVALID_SCENE);
    EXPECT_EQ(bad, nullptr);
}

// Saved while the organ turns, a clamped end's attachment restores (into a scene whose end
// was never attached) and the run continues bit for bit.
// An organ that turns about a clamped end's end point: the point stays, the clamp turns
// and gives control point 1 a velocity, so the stability guard takes its reference again
// (Dynamics::prescribe reports the turn). Every step passes at once, with every integrator.
TEST(Anatomy, AnOrganTurningAboutAClampedEndIsNotEnergyFromNothing) {
    for (const char* integrator : {"implicit_euler", "bdf2", "symplectic_euler", "rk4"}) {
        SCOPED_TRACE(integrator);
        ScenePtr scene = capi_test::create_json(std::string(R"({"intestine": {"length": 0.4, "control_points": 16,
            "shape": {"kind": "line", "center": [0, 0, 0], "direction": [1, 0, 0]}}, "gravity": [0, 0, 0],
            "damping": {}, "solver": {"integrator": ")") + integrator + R"("}, "pinned": {"clamped": "first",
            "clamped_attached": {"first": 0}}, "environment": [{"type": "sphere", "position": [-0.2, 0, 0],
            "center": [0, 0, 0.3], "radius": 0.02}]})");
        ASSERT_TRUE(scene);
        const double position[3] = {-0.2, 0.0, 0.0};
        for (int i = 1; i <= 100; ++i) {
            const double angle = 2.0 * M_PI / 180.0 * std::min(i, 45);  // 2 degrees a step (35 rad/s), then held
            const double q[4] = {std::cos(angle / 2), 0.0, 0.0, std::sin(angle / 2)};
            ASSERT_EQ(ent_obstacle_set_pose(scene.get(), 0, position, q), ENT_OK) << ent_last_error();
            ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
        }
        const ent_stats s = capi_test::stats(scene.get());
        EXPECT_EQ(s.rollbacks, 0u);
        EXPECT_GT(s.kinetic_energy_J, 0.0) << "the bowel turned";
    }
}

TEST(SaveRestore, AClampedEndOnATurningObstacleContinuesBitIdentically) {
    for (const char* integrator : {"implicit_euler", "rk4"}) {
        SCOPED_TRACE(integrator);
        ScenePtr scene = capi_test::create_json(clamped_on_organ_json(integrator, false));
        ASSERT_TRUE(scene);
        ASSERT_EQ(ent_scene_attach_clamped_end(scene.get(), ENT_PIN_FIRST, 0), ENT_OK) << ent_last_error();
        move_organ(scene.get(), 0, 200);
        std::size_t size = 0;
        ASSERT_EQ(ent_scene_save_state(scene.get(), nullptr, 0, &size), ENT_OK);
        std::vector<unsigned char> image(size);
        ASSERT_EQ(ent_scene_save_state(scene.get(), image.data(), size, &size), ENT_OK) << ent_last_error();
        move_organ(scene.get(), 200, 300);
        const std::vector<double> expected = capi_test::control_points(scene.get());

        ScenePtr fresh = capi_test::create_json(clamped_on_organ_json(integrator, false));
        ASSERT_TRUE(fresh);
        ASSERT_EQ(ent_scene_restore_state(fresh.get(), image.data(), image.size()), ENT_OK) << ent_last_error();
        move_organ(fresh.get(), 200, 300);
        EXPECT_TRUE(capi_test::control_points(fresh.get()) == expected);
    }
}

TEST(Anatomy, GravityChangesBetweenSteps) {
    const double start[3] = {0.0, 0.0, 0.0};
    ScenePtr scene = line_bowel(start, 0.3, 12, true);
    ASSERT_TRUE(scene);
    const double sideways[3] = {4.0, 0.0, 0.0};
    ASSERT_EQ(ent_scene_set_gravity(scene.get(), sideways), ENT_OK);
    ASSERT_TRUE(anatomy_step_n(scene.get(), 100));
    const std::vector<double> p = capi_test::control_points(scene.get());
    double x = 0.0, z = 0.0;
    for (std::size_t i = 0; i < p.size(); i += 3) x += p[i] - 0.3 * double(i / 3) / 11.0, z += p[i + 2];
    const double n = double(p.size() / 3);
    // Free fall under (4, 0, 0) for 0.1 s: 2 cm along x, nothing along z.
    EXPECT_NEAR(x / n, 0.5 * 4.0 * 0.01, 2e-3);
    EXPECT_NEAR(z / n, 0.0, 1e-6);
    const double bad[3] = {0.0, std::nan(""), 0.0};
    EXPECT_EQ(ent_scene_set_gravity(scene.get(), bad), ENT_ERROR_INVALID_ARGUMENT);
    // A scene without gravity gets it.
    ScenePtr weightless = line_bowel(start, 0.3, 12, false);
    EXPECT_EQ(capi_test::effect_stats(weightless.get(), ENT_EFFECT_GRAVITY).enabled, 0);
    ASSERT_EQ(ent_scene_set_gravity(weightless.get(), sideways), ENT_OK);
    EXPECT_EQ(capi_test::effect_stats(weightless.get(), ENT_EFFECT_GRAVITY).enabled, 1);
}

// On a slope of 20 degrees, a frictionless obstacle lets the bowel slide; mu = 1 holds it.
TEST(Anatomy, FrictionIsPerObstacle) {
    auto slide = [](double friction) {
        const double start[3] = {-0.15, 0.0, 0.0125};
        ScenePtr scene = line_bowel(start, 0.3, 12, true);
        const double angle = 20.0 * M_PI / 180.0;
        const double g[3] = {9.81 * std::sin(angle), 0.0, -9.81 * std::cos(angle)};  // the slope as tilted gravity
        EXPECT_EQ(ent_scene_set_gravity(scene.get(), g), ENT_OK);
        ent_obstacle_desc floor;
        ent_obstacle_desc_default(&floor);
        floor.kind = ENT_OBSTACLE_PLANE;
        const int32_t id = add(scene.get(), floor);
        EXPECT_EQ(ent_obstacle_set_friction(scene.get(), id, friction), ENT_OK);
        anatomy_step_n(scene.get(), 500);
        return capi_test::control_points(scene.get())[0] - start[0];
    };
    const double slippery = slide(0.0), sticky = slide(1.0);
    EXPECT_GT(slippery, 0.1);  // 1/2 g sin(20) t^2 = 0.42 m free; the drag slows it
    EXPECT_LT(sticky, 0.01);
}

TEST(Anatomy, ObstaclesCanBeRemoved) {
    const double start[3] = {-0.15, 0.0, 0.0125};
    ScenePtr scene = line_bowel(start, 0.3, 12, true);
    ent_obstacle_desc floor;
    ent_obstacle_desc_default(&floor);
    floor.kind = ENT_OBSTACLE_PLANE;
    const int32_t a = add(scene.get(), floor);
    floor.center_m[2] = -1.0;
    const int32_t b = add(scene.get(), floor);
    uint32_t count = 0;
    ASSERT_EQ(ent_scene_obstacle_count(scene.get(), &count), ENT_OK);
    EXPECT_EQ(count, 2u);
    ASSERT_TRUE(anatomy_step_n(scene.get(), 200));
    EXPECT_GT(capi_test::control_points(scene.get())[2], 0.0);
    ASSERT_EQ(ent_scene_remove_obstacle(scene.get(), a), ENT_OK);
    ASSERT_EQ(ent_scene_obstacle_count(scene.get(), &count), ENT_OK);
    EXPECT_EQ(count, 1u);
    EXPECT_EQ(ent_scene_remove_obstacle(scene.get(), a), ENT_ERROR_NOT_FOUND);
    const double q[4] = {1, 0, 0, 0}, at[3] = {0, 0, 0};
    EXPECT_EQ(ent_obstacle_set_pose(scene.get(), a, at, q), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_obstacle_set_pose(scene.get(), 9, at, q), ENT_ERROR_NOT_FOUND);
    double position[3], orientation[4];
    EXPECT_EQ(ent_obstacle_pose(scene.get(), a, position, orientation), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_obstacle_pose(scene.get(), b, position, orientation), ENT_OK);
    ASSERT_TRUE(anatomy_step_n(scene.get(), 200));
    EXPECT_LT(capi_test::control_points(scene.get())[2], -0.1) << "falls once the floor is gone";
}

// A scene file names its meshes relative to its own directory.
TEST(Anatomy, ASceneFileReadsItsMeshFilesRelativeToItself) {
    const std::string directory = ::testing::TempDir() + "enteron_anatomy_scene";
    ASSERT_EQ(std::system(("mkdir -p " + directory + "/organs").c_str()), 0);
    const double c[3] = {0.0, 0.0, -0.1};
    const Mesh m = icosphere(c, 0.05, 2);
    {
        std::ofstream obj(directory + "/organs/ball.obj");
        obj << "# a ball\n";
        for (std::size_t i = 0; i < m.vertices.size(); i += 3)
            obj << "v " << 1000 * m.vertices[i] << " " << 1000 * m.vertices[i + 1] << " " << 1000 * m.vertices[i + 2] << "\n";
        for (std::size_t i = 0; i < m.triangles.size(); i += 3)
            obj << "f " << m.triangles[i] + 1 << " " << m.triangles[i + 1] + 1 << " " << m.triangles[i + 2] + 1 << "\n";
        std::ofstream ply(directory + "/organs/ball.ply");
        ply << "ply\nformat ascii 1.0\nelement vertex " << m.vertices.size() / 3
            << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << m.triangles.size() / 3
            << "\nproperty list uchar int vertex_indices\nend_header\n";
        for (std::size_t i = 0; i < m.vertices.size(); i += 3)
            ply << m.vertices[i] << " " << m.vertices[i + 1] << " " << m.vertices[i + 2] << "\n";
        for (std::size_t i = 0; i < m.triangles.size(); i += 3)
            ply << "3 " << m.triangles[i] << " " << m.triangles[i + 1] << " " << m.triangles[i + 2] << "\n";
        std::ofstream scene(directory + "/scene.json");
        scene << R"({"intestine": {"length": 0.3, "control_points": 12, "shape": {"kind": "line"}},
                     "environment": [{"type": "mesh", "file": "organs/ball.obj", "scale": 0.001},
                                     {"type": "mesh", "file": "organs/ball.ply", "position": [0, 0, -0.2]}]})";
        std::ofstream missing(directory + "/missing.json");
        missing << R"({"environment": [{"type": "mesh", "file": "organs/liver.obj"}]})";
    }
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create_json_file((directory + "/scene.json").c_str(), nullptr, &scene), ENT_OK)
        << ent_last_error();
    uint32_t vertices = 0, triangles = 0;
    EXPECT_EQ(ent_obstacle_mesh(scene, 0, 0, nullptr, &vertices, 0, nullptr, &triangles), ENT_OK) << ent_last_error();
    EXPECT_EQ(vertices, m.vertices.size() / 3);
    EXPECT_EQ(triangles, m.triangles.size() / 3);
    std::vector<double> read(3 * vertices);
    EXPECT_EQ(ent_obstacle_mesh(scene, 1, vertices, read.data(), &vertices, 0, nullptr, &triangles), ENT_OK);
    EXPECT_NEAR(read[0], m.vertices[0], 1e-6);
    ent_scene_destroy(scene);
    scene = nullptr;
    EXPECT_EQ(ent_scene_create_json_file((directory + "/missing.json").c_str(), nullptr, &scene),
              ENT_ERROR_INVALID_SCENE);
    EXPECT_NE(std::string(ent_last_error()).find("environment[0].file"), std::string::npos) << ent_last_error();
    EXPECT_NE(std::string(ent_last_error()).find("organs/liver.obj"), std::string::npos) << ent_last_error();
    EXPECT_EQ(scene, nullptr);
    EXPECT_EQ(ent_scene_create_json_file((directory + "/none.json").c_str(), nullptr, &scene),
              ENT_ERROR_INVALID_ARGUMENT);
}

}  // namespace
