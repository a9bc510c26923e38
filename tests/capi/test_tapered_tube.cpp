// SPDX-License-Identifier: Apache-2.0
// A tube whose radius falls linearly from 3.5 cm to 1.3 cm along its 1.5 m (the colon's
// caecum to its sigmoid, docs/anatomy.md), settled on a floor: every skin draws the
// profile's radius at each place, within the bounds of the constant tube (test_skin.cpp);
// a tool grasps its thin end at the thin end's radius, and a tool as far from the thin
// end's surface as the largest radius would reach is out of reach.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "skin_test_support.h"

using namespace capi_test;
using namespace skin_test;

namespace {

constexpr double kTaperedWide = 0.035, kTaperedThin = 0.013, kTaperedLength = 1.5;
constexpr uint32_t kTaperedPoints = 61;

double tapered_radius(double s) {
    return kTaperedWide + (kTaperedThin - kTaperedWide) * std::clamp(s / kTaperedLength, 0.0, 1.0);
}

// Along x from the origin, on the floor z = 0, settled for `settle` steps of 1 ms.
ScenePtr tapered_tube_on_floor(int settle) {
    static const double radius[4] = {0.0, kTaperedWide, kTaperedLength, kTaperedThin};
    ent_scene_desc desc = default_desc();
    desc.control_points = kTaperedPoints;
    desc.length_m = kTaperedLength;
    desc.radius_profile_m = radius;
    desc.radius_profile_count = 2;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_center_m[2] = kTaperedWide + 0.001;  // above the floor by the largest radius (and 1 mm)
    desc.integrator = ENT_INTEGRATOR_IMPLICIT_EULER;
    desc.drag_N_s_per_m2 = 1.0;
    ScenePtr scene = create(desc);
    if (!scene) return scene;
    ent_obstacle_desc floor;
    ent_obstacle_desc_default(&floor);
    floor.kind = ENT_OBSTACLE_PLANE;
    int32_t index = -1;
    EXPECT_EQ(ent_scene_add_obstacle(scene.get(), &floor, &index), ENT_OK) << ent_last_error();
    EXPECT_TRUE(step_n(scene.get(), 0.001, settle));
    return scene;
}

TEST(TaperedTube, EverySkinDrawsTheProfilesRadiusAtEachPlace) {
    ScenePtr scene = tapered_tube_on_floor(1000);
    ASSERT_TRUE(scene);
    for (int32_t method : {ENT_SKIN_TUBE, ENT_SKIN_POINT_SKELETON, ENT_SKIN_CONVOLUTION}) {
        SkinPtr skin = make_skin(scene.get(), method);
        ASSERT_TRUE(skin);
        ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
        const struct ent_skin_metrics m = metrics(skin.get());
        // The constant tube's bounds: RMS under half a percent, 2 % anywhere (test_skin.cpp),
        // each vertex against the profile's radius at its place.
        EXPECT_LT(m.radius_error_rms, 0.005) << "method " << method;
        EXPECT_LT(m.radius_error_max, 0.02) << "method " << method;
        EXPECT_LT(m.free_radius_error_rms, 0.005) << "method " << method;
        EXPECT_EQ(m.watertight, 1) << "method " << method;
        // Independently of the metrics: the tube lies along x on the floor, each part on its
        // own radius, so a vertex above x (away from the ends) is r(x) from the axis at
        // height r(x): its height spans [0, 2 r(x)].
        const ent_mesh_view view = mesh(skin.get());
        double lowest = 1.0, highest_over_diameter = 0.0;
        for (uint32_t i = 0; i < view.vertex_count; ++i) {
            const double x = view.positions_xyz_m[3 * i], z = view.positions_xyz_m[3 * i + 2];
            if (x < 0.1 || x > kTaperedLength - 0.1) continue;
            lowest = std::min(lowest, z);
            highest_over_diameter = std::max(highest_over_diameter, z / (2 * tapered_radius(x)));
        }
        EXPECT_NEAR(lowest, 0.0, 0.001) << "method " << method;
        EXPECT_NEAR(highest_over_diameter, 1.0, 0.02) << "method " << method;
        std::printf("[ tapered ] method %d: radius error RMS %.3f %% max %.3f %%, free RMS %.3f %%, "
                    "top %.4f of 2 r(x)\n",
                    method, 100 * m.radius_error_rms, 100 * m.radius_error_max, 100 * m.free_radius_error_rms,
                    highest_over_diameter);
    }
}

// Where the axis at arc length about s (the point of the axis of 301 samples nearest x = s)
// lies from the tip: its distance, m.
double tapered_distance_to_axis(const ent_scene* scene, const double tip[3]) {
    std::vector<double> axis(3 * 301);
    EXPECT_EQ(ent_scene_axis(scene, 301, axis.data()), ENT_OK) << ent_last_error();
    double nearest = 1e300;
    for (std::size_t i = 0; i < axis.size(); i += 3)
        nearest = std::min(nearest, std::hypot(axis[i] - tip[0], axis[i + 1] - tip[1], axis[i + 2] - tip[2]));
    return nearest;
}

int32_t tapered_tool_above(ent_scene* scene, double x, double height) {
    ent_tool_desc desc;
    ent_tool_desc_default(&desc);
    desc.mode = ENT_TOOL_MODE_DIRECT;
    desc.position_m[0] = x;
    desc.position_m[2] = height;
    int32_t id = -1;
    EXPECT_EQ(ent_tool_add(scene, &desc, &id), ENT_OK) << ent_last_error();
    return id;
}

int32_t tapered_grasping(const ent_scene* scene, int32_t tool) {
    int32_t out = -1;
    EXPECT_EQ(ent_tool_state(scene, tool, &out), ENT_OK) << ent_last_error();
    return out;
}

TEST(TaperedTube, AToolGraspsTheThinEndAtItsOwnRadius) {
    ScenePtr scene = tapered_tube_on_floor(300);
    ASSERT_TRUE(scene);
    ent_tool_desc defaults;
    ent_tool_desc_default(&defaults);
    const double tool_radius = defaults.radius_m, margin = defaults.grasp_margin_m;
    const double x = 1.4, r = tapered_radius(x);
    // 4 mm above the thin end's surface (within grasp_margin, 5 mm): held, and the grasp's
    // spring closes to the tool's radius plus the thin end's, lifting it the 4 mm. (At the
    // largest radius the spring would stay slack 2.2 cm further out.)
    const double tip[3] = {x, 0.0, 2 * r + tool_radius + 0.004};
    const int32_t tool = tapered_tool_above(scene.get(), x, tip[2]);
    ASSERT_TRUE(step_n(scene.get(), 0.001, 1));
    ASSERT_EQ(ent_tool_grasp(scene.get(), tool), ENT_OK) << ent_last_error();
    ASSERT_TRUE(step_n(scene.get(), 0.001, 1));
    ASSERT_EQ(tapered_grasping(scene.get(), tool), 1);
    const double before = tapered_distance_to_axis(scene.get(), tip);
    ASSERT_TRUE(step_n(scene.get(), 0.001, 400));
    EXPECT_EQ(tapered_grasping(scene.get(), tool), 1);
    const double held = tapered_distance_to_axis(scene.get(), tip);
    // The held point hangs below the spring's rest length by its stretch under the weight it
    // lifts (the force on the tool over the spring's stiffness): the rest length is the
    // tool's radius plus the thin end's.
    double force[3], torque[3];
    ASSERT_EQ(ent_tool_wrench(scene.get(), tool, force, torque), ENT_OK) << ent_last_error();
    const double stretch = std::hypot(force[0], force[1], force[2]) / defaults.grasp_stiffness_N_per_m;
    std::printf("[ tapered grasp ] tip to axis %.2f mm, then held at %.2f mm, %.2f mm beyond the spring's rest "
                "(tool + thin radius %.2f mm, + largest %.2f mm)\n",
                1e3 * before, 1e3 * held, 1e3 * stretch, 1e3 * (tool_radius + r), 1e3 * (tool_radius + kTaperedWide));
    EXPECT_GT(before - held, 0.001) << "the spring closed";
    EXPECT_NEAR(held - stretch, tool_radius + r, 0.0005);

    // A tool beyond grasp_margin of the thin end's surface, though within the margin of
    // where the largest radius' surface would be, holds nothing.
    const double out_of_reach = r + tool_radius + margin + 0.005;
    ASSERT_LT(out_of_reach, kTaperedWide + tool_radius + margin);
    ScenePtr other = tapered_tube_on_floor(300);
    ASSERT_TRUE(other);
    const int32_t far = tapered_tool_above(other.get(), x, r + out_of_reach);
    ASSERT_TRUE(step_n(other.get(), 0.001, 1));
    ASSERT_EQ(ent_tool_grasp(other.get(), far), ENT_OK) << ent_last_error();
    ASSERT_TRUE(step_n(other.get(), 0.001, 1));
    EXPECT_EQ(tapered_grasping(other.get(), far), 0);
}

}  // namespace
