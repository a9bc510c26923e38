// SPDX-License-Identifier: Apache-2.0
// Running the bowel: two graspers with jaws pass a bowel hand over hand, as a surgeon
// inspects it span by span. Each grasp takes hold within 1 cm of the span aimed at (what
// ent_tool_read_contacts' grasp_u says), and the grasper let go holds nothing and feels
// nothing once lifted clear.
#include "capi_scenes.h"

#include <algorithm>
#include <iostream>

#include "test_helpers.h"

using namespace capi_test;

namespace {

using enteron_test::kIdentity;
using enteron_test::norm3;

constexpr double kRunLength = 0.8;  // m
constexpr double kRunToolRadius = 0.005;

struct Hands {
    ScenePtr scene;
    int32_t tool[2] = {-1, -1};
    double at[2][3] = {{-0.35, 0.0, 0.15}, {-0.30, 0.0, 0.15}};  // each grasper's commanded tip
};

// The point of the axis at arc length s from the first end (the axis sampled every mm).
void axis_point(const ent_scene* scene, double s, double out[3]) {
    const uint32_t count = 801;
    std::vector<double> xyz(3 * count);
    EXPECT_EQ(ent_scene_axis(scene, count, xyz.data()), ENT_OK) << ent_last_error();
    const std::size_t i = std::min<std::size_t>(count - 1, static_cast<std::size_t>(std::lround(s / kRunLength * (count - 1))));
    for (int c = 0; c < 3; ++c) out[c] = xyz[3 * i + c];
}

// Moves grasper g's commanded tip in a straight line to `to` over `steps` steps of 1 ms.
void move(Hands& h, int g, const double to[3], int steps) {
    const double from[3] = {h.at[g][0], h.at[g][1], h.at[g][2]};
    for (int i = 1; i <= steps; ++i) {
        const double a = static_cast<double>(i) / steps;
        for (int c = 0; c < 3; ++c) h.at[g][c] = (1 - a) * from[c] + a * to[c];
        ASSERT_EQ(ent_tool_set_pose(h.scene.get(), h.tool[g], h.at[g], kIdentity), ENT_OK) << ent_last_error();
        ASSERT_EQ(ent_scene_step(h.scene.get(), 1e-3), ENT_OK) << ent_last_error();
    }
}

ent_tool_contacts contacts_of(const Hands& h, int g) {
    ent_tool_contacts t{};
    t.struct_size = sizeof t;
    EXPECT_EQ(ent_tool_read_contacts(h.scene.get(), h.tool[g], &t), ENT_OK) << ent_last_error();
    return t;
}

}  // namespace

TEST(RunningTheBowel, TwoGraspersPassTheBowelHandOverHand) {
    BowelOnPlane bowel;
    bowel.length_m = kRunLength;
    bowel.control_points = 65;
    bowel.settle_s = 0.1;
    Hands h;
    h.scene = bowel_on_plane(bowel);
    ASSERT_TRUE(h.scene);
    for (int g = 0; g < 2; ++g) {
        ent_tool_desc desc;
        ent_tool_desc_default(&desc);
        desc.radius_m = kRunToolRadius;
        desc.jaw_length_m = 0.02;
        desc.jaw_opening_m = 0.015;
        for (int c = 0; c < 3; ++c) desc.position_m[c] = h.at[g][c];
        ASSERT_EQ(ent_tool_add(h.scene.get(), &desc, &h.tool[g]), ENT_OK) << ent_last_error();
    }
    double worst = 0.0;
    const int hops = 10;
    for (int k = 0; k < hops; ++k) {
        const int g = k % 2, other = 1 - g;
        const double aimed = 0.15 + 0.05 * k;  // m from the first end: 5 cm a hop
        // Over the span, down to 1 cm above it, and onto it as it is then (the bowel still
        // swings from the last lift): the jaws 3 mm above the tube's top.
        double p[3];
        axis_point(h.scene.get(), aimed, p);
        const double over[3] = {p[0], p[1], 0.1};
        move(h, g, over, 150);
        axis_point(h.scene.get(), aimed, p);
        const double near[3] = {p[0], p[1], p[2] + kBowelRadius + kRunToolRadius + 0.01};
        move(h, g, near, 100);
        move(h, g, near, 100);  // wait for the span to come to rest
        axis_point(h.scene.get(), aimed, p);
        const double on[3] = {p[0], p[1], p[2] + kBowelRadius + kRunToolRadius + 0.003};
        move(h, g, on, 50);
        ASSERT_EQ(ent_tool_grasp(h.scene.get(), h.tool[g]), ENT_OK) << ent_last_error();
        ASSERT_TRUE(step_n(h.scene.get(), 1e-3, 1));
        const ent_tool_contacts held = contacts_of(h, g);
        ASSERT_EQ(held.grasping, 1) << "hop " << k;
        const double off = std::fabs(held.grasp_u * kRunLength - aimed);
        worst = std::max(worst, off);
        EXPECT_LE(off, 0.01) << "hop " << k << ": took hold " << off << " m from the span aimed at";
        // Lift to 6 cm above the floor, then the other hand lets go and rises clear.
        const double lifted[3] = {on[0], on[1], 0.06};
        move(h, g, lifted, 200);
        EXPECT_EQ(contacts_of(h, g).grasping, 1) << "hop " << k << ": the lift holds";
        if (k > 0) {
            ASSERT_EQ(ent_tool_release(h.scene.get(), h.tool[other]), ENT_OK) << ent_last_error();
            ASSERT_TRUE(step_n(h.scene.get(), 1e-3, 1));
            EXPECT_EQ(contacts_of(h, other).grasping, 0) << "hop " << k;
            const double clear[3] = {h.at[other][0], h.at[other][1], 0.15};
            move(h, other, clear, 200);
            double force[3], torque[3];
            ASSERT_EQ(ent_tool_wrench(h.scene.get(), h.tool[other], force, torque), ENT_OK) << ent_last_error();
            EXPECT_LT(norm3(force), 1e-9) << "hop " << k << ": the hand let go feels nothing once clear";
            EXPECT_EQ(contacts_of(h, other).contacts, 0u) << "hop " << k;
        }
    }
    std::cout << "[ running the bowel ] " << hops << " hops of 5 cm, farthest grasp from its span " << worst * 1e3
              << " mm\n";
}
