// Checks of the MuJoCo peer against what must hold whatever MuJoCo's contact model does:
// the chain starts exactly on the given axis, its free fall follows g t^2 / 2 (internal
// joint forces cannot move the centre of mass), a pinned end stays put, and the
// arc-length axis spans the rope's length. Built and run only with ENTERON_BENCH_MUJOCO.
#include "peers/mujoco_rope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using enteron::peers::MujocoRope;
using enteron::peers::MujocoRopeDesc;

ent_scene_desc scene_desc(uint32_t points) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.control_points = points;
    desc.length_m = 1.0;
    desc.shape = ENT_SHAPE_LINE;
    return desc;
}

std::unique_ptr<MujocoRope> make(const MujocoRopeDesc& desc) {
    std::string error;
    auto rope = MujocoRope::create(desc, &error);
    EXPECT_NE(rope, nullptr) << error;
    return rope;
}

double mean_z(const std::vector<double>& points) {
    double z = 0.0;
    for (std::size_t i = 2; i < points.size(); i += 3) z += points[i];
    return z / static_cast<double>(points.size() / 3);
}

TEST(MujocoRope, StartsOnTheGivenAxis) {
    // A bent polyline: a quarter circle of radius 0.2 m, then a straight leg.
    const uint32_t n = 21;
    MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene_desc(n));
    const double l = desc.length_m / (n - 1);
    desc.initial_points_xyz_m.assign(3 * n, 0.0);
    double heading = 0.0;
    for (uint32_t i = 1; i < n; ++i) {
        heading += i < 10 ? l / 0.2 : 0.0;
        desc.initial_points_xyz_m[3 * i + 0] = desc.initial_points_xyz_m[3 * (i - 1) + 0] + l * std::cos(heading);
        desc.initial_points_xyz_m[3 * i + 1] = desc.initial_points_xyz_m[3 * (i - 1) + 1] + l * 0.6 * std::sin(heading);
        desc.initial_points_xyz_m[3 * i + 2] = desc.initial_points_xyz_m[3 * (i - 1) + 2] + l * 0.8 * std::sin(heading);
    }
    auto rope = make(desc);
    ASSERT_NE(rope, nullptr);
    std::vector<double> points;
    rope->joint_points(points);
    ASSERT_EQ(points.size(), desc.initial_points_xyz_m.size());
    for (std::size_t k = 0; k < points.size(); ++k) EXPECT_NEAR(points[k], desc.initial_points_xyz_m[k], 1e-9) << k;
}

TEST(MujocoRope, FallsFreelyLikeItsCentreOfMass) {
    MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene_desc(31));
    ASSERT_EQ(desc.initial_points_xyz_m.size(), 3u * 31);  // the line shape gives the axis
    auto rope = make(desc);
    ASSERT_NE(rope, nullptr);
    std::vector<double> before, after;
    rope->joint_points(before);
    ASSERT_TRUE(rope->advance_to(0.2));
    rope->joint_points(after);
    EXPECT_TRUE(rope->finite());
    EXPECT_EQ(rope->contacts(), 0);
    // Joint forces are internal: every point of the unsupported rope falls g t^2 / 2, to
    // within the first-order integrator's lag of a step, g t h. Without contacts nothing
    // else acts; a wrong mass, gravity or joint placement would show here.
    const double t = rope->time_s();
    const double h = desc.timestep_s;
    EXPECT_NEAR(mean_z(after) - mean_z(before), -0.5 * 9.81 * t * t, 9.81 * t * h);
    for (std::size_t k = 0; k < after.size(); k += 3) {
        EXPECT_NEAR(after[k], before[k], 1e-9);  // a horizontal rope falls straight down
        EXPECT_NEAR(after[k + 2] - before[k + 2], -0.5 * 9.81 * t * t, 9.81 * t * h);
    }
}

TEST(MujocoRope, PinnedEndStaysAndTheAxisKeepsItsLength) {
    ent_scene_desc scene = scene_desc(21);
    scene.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    scene.pinned_ends = ENT_PIN_FIRST;
    const MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene);
    ASSERT_TRUE(desc.pin_first);
    auto rope = make(desc);
    ASSERT_NE(rope, nullptr);
    ASSERT_TRUE(rope->advance_to(0.3));
    std::vector<double> points, axis;
    rope->joint_points(points);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(points[c], desc.initial_points_xyz_m[c], 1e-9);
    EXPECT_LT(points[3 * 20 + 2], -0.05);  // the free end swung down
    rope->axis(101, axis);
    ASSERT_EQ(axis.size(), 3u * 101);
    double length = 0.0;
    for (std::size_t i = 1; i < 101; ++i) {
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c) d2 += (axis[3 * i + c] - axis[3 * i - 3 + c]) * (axis[3 * i + c] - axis[3 * i - 3 + c]);
        length += std::sqrt(d2);
    }
    EXPECT_NEAR(length, desc.length_m, 0.01 * desc.length_m);  // rigid segments; chords cut corners
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(axis[3 * 100 + c], points[3 * 20 + c], 1e-12);
}

TEST(MujocoRope, RefusesAWrongAxis) {
    MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene_desc(10));
    desc.initial_points_xyz_m.resize(6);
    std::string error;
    EXPECT_EQ(MujocoRope::create(desc, &error), nullptr);
    EXPECT_NE(error.find("initial_points_xyz_m"), std::string::npos) << error;
}

}  // namespace
