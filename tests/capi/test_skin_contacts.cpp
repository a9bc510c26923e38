// SPDX-License-Identifier: Apache-2.0
// Contact surfaces through the C API (ent_skin_desc.contact_surfaces, the contact measures
// of ent_skin_metrics): a fold of a small pile pressed by a tool into the folds beneath.
// The skins' surfaces meet on the contact instead of passing through each other, the
// volume stays, nothing folds over; without contact surfaces the press shows as overlap.
#include "skin_test_support.h"

#include <algorithm>
#include <cmath>

using namespace capi_test;
using namespace skin_test;

namespace {

constexpr double kR = 0.0125;
const double kIdentity[4] = {1.0, 0.0, 0.0, 0.0};

// A limp 0.6 m bowel released as a coil into a small box: after 1.5 s it lies in a pile of
// loops resting on each other. Returns the highest point of its axis in `top`.
ScenePtr small_pile(double top[3]) {
    ScenePtr scene = create_json(
        "{\"intestine\": {\"length\": 0.6, \"radius\": 0.0125, \"control_points\": 48, \"linear_density\": 0.3,"
        " \"stretch_stiffness\": 100, \"bend_stiffness\": 2e-5,"
        " \"shape\": {\"kind\": \"helix\", \"center\": [0, 0, 0.05], \"helix_radius\": 0.03, \"helix_pitch\": 0.03}},"
        " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001}, \"gravity\": [0, 0, -9.81],"
        " \"damping\": {\"drag\": 0.05, \"stretch\": 0.05, \"bend\": 0},"
        " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0.1], \"half_extents\": [0.06, 0.06, 0.1]}],"
        " \"self_collision\": {}}");
    if (!scene) return scene;
    for (int i = 0; i < 1500; ++i) EXPECT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << ent_last_error();
    const std::vector<double> q = control_points(scene.get());
    top[2] = -1.0;
    for (std::size_t i = 0; i < q.size(); i += 3)
        if (q[i + 2] > top[2]) std::copy(&q[i], &q[i] + 3, top);
    return scene;
}

struct ent_skin_metrics skin_of(ent_scene* scene, int32_t method, int32_t contacts) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    EXPECT_EQ(desc.contact_surfaces, 1);  // the default
    desc.method = method;
    desc.contact_surfaces = contacts;
    SkinPtr skin = make_skin(scene, desc);
    EXPECT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
    return metrics(skin.get());
}

TEST(SkinContacts, AFoldPressedByAToolMeetsTheFoldBeneath) {
    double top[3];
    ScenePtr scene = small_pile(top);
    ASSERT_TRUE(scene);
    // A vertical tool comes down on the pile's highest fold and presses it, with 8 N, into
    // the folds beneath.
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    tool.max_force_N = 8.0;
    std::copy(top, top + 3, tool.position_m);
    tool.position_m[2] += 2.0 * kR;
    int32_t id = -1;
    ASSERT_EQ(ent_tool_add(scene.get(), &tool, &id), ENT_OK) << ent_last_error();
    for (int i = 1; i <= 500; ++i) {
        const double p[3] = {top[0], top[1], top[2] + 2.0 * kR - 4.0 * kR * std::min(1.0, i / 300.0)};
        ASSERT_EQ(ent_tool_set_pose(scene.get(), id, p, kIdentity), ENT_OK) << ent_last_error();
        ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << ent_last_error();
    }
    // Pressed: the folds' tubes overlap by far more than when they rest on each other.
    const struct ent_skin_metrics through = skin_of(scene.get(), ENT_SKIN_CONVOLUTION, 0);
    ASSERT_GT(through.tube_overlap_depth_max, 0.15);
    EXPECT_GT(through.overlap_depth_max, 0.1);  // the surfaces pass through each other
    EXPECT_GT(through.overlap_area_m2, 0.0);
    // With contact surfaces (the default) they meet: no overlap beyond the facets' sag, no
    // gap, the volume the same to a fraction of a percent, nothing folded over.
    const struct ent_skin_metrics met = skin_of(scene.get(), ENT_SKIN_CONVOLUTION, 1);
    EXPECT_LT(met.overlap_depth_max, 0.03);
    EXPECT_EQ(met.overlap_area_m2, 0.0);
    EXPECT_LT(met.contact_gap_max, 0.03);
    EXPECT_LT(std::fabs(met.shape_volume_error), 0.003);
    EXPECT_NEAR(met.volume_m3, through.volume_m3, 0.003 * through.volume_m3);
    EXPECT_EQ(met.inverted_triangles, 0u);
    EXPECT_EQ(met.watertight, 1);
    // The point skeleton draws the two legs' union, swollen where they meet.
    const struct ent_skin_metrics point = skin_of(scene.get(), ENT_SKIN_POINT_SKELETON, 1);
    EXPECT_LT(point.overlap_depth_max, 0.03);
    EXPECT_LT(std::fabs(point.shape_volume_error), 0.01);
    EXPECT_EQ(point.watertight, 1);
}

}  // namespace
