// SPDX-License-Identifier: Apache-2.0
// Where a grasp takes hold (ent_tool_grasp, ent_tool_desc jaw_length_m and jaw_opening_m):
// a grasper with jaws takes the loop between them, not the nearest loop beside them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "capi_test_support.h"

using namespace capi_test;

namespace {

constexpr double kAimRadius = 0.01;       // the bowel's R, m
constexpr double kBesideJaws = 0.016;     // run A: 1.6 cm from the shaft's axis along world y
constexpr double kBetweenJaws = 0.018;    // run B: 1.8 cm along world x, farther from the tip
constexpr double kHalfTurn = 3.14159265358979323846;  // radians

// A hairpin standing beside a vertical tool whose tip is at the origin: run A rises along z
// at (0, kBesideJaws), turns over the top and comes down as run B at (kBetweenJaws, 0). Both
// runs lie within the grasp's reach of the tip (5 mm tool, R 1 cm, 5 mm margin: 2 cm) and
// out of the tool (1.5 cm); run A is the nearer.
ScenePtr aim_hairpin() {
    std::vector<double> xyz;
    const auto add = [&](double x, double y, double z) { xyz.insert(xyz.end(), {x, y, z}); };
    for (int k = 0; k <= 20; ++k) add(0.0, kBesideJaws, -0.1 + 0.01 * k);
    const double cx = 0.5 * kBetweenJaws, cy = 0.5 * kBesideJaws;
    const double rho = 0.5 * std::hypot(kBetweenJaws, kBesideJaws);
    for (int k = 1; k <= 3; ++k) {  // over the top, a half circle from A to B
        const double theta = kHalfTurn * k / 4.0;
        const double c = std::cos(theta), s = std::sin(theta);
        add(cx - c * (cx - 0.0), cy - c * (cy - kBesideJaws), 0.1 + rho * s);
    }
    for (int k = 20; k >= 0; --k) add(kBetweenJaws, 0.0, -0.1 + 0.01 * k);
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_DAMPING);
    desc.radius_m = kAimRadius;
    desc.shape = ENT_SHAPE_POINTS;
    desc.control_points = static_cast<uint32_t>(xyz.size() / 3);
    desc.shape_points_xyz_m = xyz.data();
    desc.length_m = 0.0;
    return create(desc);
}

// Adds a vertical tool at the origin (turned about z by `turn` radians), grasps, steps once
// and returns where it took hold (grasp_u; -1: nothing). `size` is the desc's struct_size.
double grasp_u_with(double jaw_length, double jaw_opening, double turn, uint32_t size = sizeof(ent_tool_desc)) {
    ScenePtr scene = aim_hairpin();
    EXPECT_TRUE(scene);
    if (!scene) return -2.0;
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    tool.jaw_length_m = jaw_length;
    tool.jaw_opening_m = jaw_opening;
    tool.orientation_wxyz[0] = std::cos(0.5 * turn);
    tool.orientation_wxyz[3] = std::sin(0.5 * turn);
    tool.struct_size = size;
    int32_t id = -1;
    EXPECT_EQ(ent_tool_add(scene.get(), &tool, &id), ENT_OK) << ent_last_error();
    EXPECT_EQ(ent_tool_grasp(scene.get(), id), ENT_OK) << ent_last_error();
    EXPECT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << ent_last_error();
    ent_tool_contacts contacts{};
    contacts.struct_size = sizeof contacts;
    EXPECT_EQ(ent_tool_read_contacts(scene.get(), id, &contacts), ENT_OK) << ent_last_error();
    EXPECT_EQ(contacts.grasping, 1);
    return contacts.grasp_u;
}

}  // namespace

TEST(GraspAim, WithoutJawsTheGraspTakesTheLoopNearestTheTip) {
    const double u = grasp_u_with(0.0, 0.0, 0.0);
    EXPECT_GT(u, 0.0);
    EXPECT_LT(u, 0.5) << "run A, 1.6 cm from the tip, before run B at 1.8 cm";
}

TEST(GraspAim, JawsTakeTheLoopBetweenThemBeforeANearerOneBesideThem) {
    // Jaws 2 cm long opening 2 cm across local x (world x): run B lies in their plane.
    const double u = grasp_u_with(0.02, 0.02, 0.0);
    EXPECT_GT(u, 0.5) << "run B, between the jaws";
    EXPECT_LT(u, 1.0);
}

TEST(GraspAim, TurningTheJawsOntoTheOtherLoopTakesIt) {
    // The same jaws turned a quarter about the shaft: they open along world y, onto run A.
    const double u = grasp_u_with(0.02, 0.02, 0.5 * kHalfTurn);
    EXPECT_GT(u, 0.0);
    EXPECT_LT(u, 0.5) << "run A, now between the jaws";
}

TEST(GraspAim, AnOlderDescWithoutJawsGraspsAsBefore) {
    // A caller built before the jaws: its struct_size stops before them, they take their
    // defaults (none), whatever lies beyond in its memory.
    const double u = grasp_u_with(0.02, 0.02, 0.0, static_cast<uint32_t>(offsetof(ent_tool_desc, jaw_length_m)));
    EXPECT_GT(u, 0.0);
    EXPECT_LT(u, 0.5);
}
