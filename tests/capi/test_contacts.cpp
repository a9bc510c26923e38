// SPDX-License-Identifier: Apache-2.0
// The published contact list (ent_scene_contacts), the bowel's summary
// (ent_scene_contact_summary) and a tool's touches (ent_tool_read_contacts), checked against
// forces the tests work out themselves: a bowel pressed into a plane at a known depth gets
// the penalty law's k d from every sphere; two folds overlapping at rest push apart with
// k times their depth along their normal; a tool's contacts add up to minus its wrench, and
// their torques about the tip to minus its torque; a stretched axis reports its stretch.
#include "capi_scenes.h"

#include <iostream>

#include "test_helpers.h"

using namespace capi_test;

namespace {

using enteron_test::norm3;
using enteron_test::kIdentity;

constexpr double kRadius = kBowelRadius;  // the default R, m
constexpr double kStiffness = 500.0;   // the default contact stiffness, N/m


std::vector<ent_contact> contacts(const ent_scene* scene) {
    const ent_contact_summary s = summary(scene);
    std::vector<ent_contact> list(std::max<uint32_t>(s.capacity, 1));
    list[0].struct_size = sizeof(ent_contact);
    uint32_t count = 0;
    EXPECT_EQ(ent_scene_contacts(scene, static_cast<uint32_t>(list.size()), list.data(), &count), ENT_OK)
        << ent_last_error();
    list.resize(count);
    return list;
}

ent_tool_contacts tool_contacts(const ent_scene* scene, int32_t tool, std::vector<double>* ranges) {
    ent_tool_contacts t;
    std::memset(&t, 0, sizeof t);
    t.struct_size = sizeof t;
    if (ranges != nullptr) {
        t.range_capacity = static_cast<uint32_t>(ranges->size() / 2);
        t.ranges_u = ranges->data();
    }
    EXPECT_EQ(ent_tool_read_contacts(scene, tool, &t), ENT_OK) << ent_last_error();
    return t;
}

// A straight bowel along x whose axis lies at height z = R - depth above the plane z = 0,
// at rest, without gravity: every collision sphere reaches `depth` into the plane.
ScenePtr bowel_pressed_into_plane(double depth) {
    BowelOnPlane bowel;
    bowel.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND);
    bowel.length_m = 0.3;
    bowel.control_points = 13;
    bowel.axis_height_m = kRadius - depth;
    return bowel_on_plane(bowel);
}

// Two parallel legs `gap` apart (axis to axis, less than 2R: they overlap) joined by a
// half turn, as control points every `chord` metres.
std::vector<double> hairpin(double leg, double gap, uint32_t count, double* length) {
    const double pi = 3.14159265358979323846, rho = 0.5 * gap;
    *length = 2 * leg + pi * rho;
    std::vector<double> points;
    for (uint32_t i = 0; i < count; ++i) {
        const double s = *length * i / (count - 1);
        double x, y;
        if (s < leg) {
            x = s, y = 0.0;
        } else if (s < leg + pi * rho) {
            const double angle = (s - leg) / rho;
            x = leg + rho * std::sin(angle), y = rho - rho * std::cos(angle);
        } else {
            x = leg - (s - leg - pi * rho), y = gap;
        }
        points.insert(points.end(), {x, y, 0.0});
    }
    return points;
}

TEST(Contacts, NoneBeforeTheFirstStepAndNoneWithoutContactEffects) {
    ScenePtr plain = create(default_desc());
    ASSERT_TRUE(plain);
    ASSERT_TRUE(step_n(plain.get(), 1e-3, 3));
    const ent_contact_summary s = summary(plain.get());
    EXPECT_EQ(s.capacity, 0u);
    EXPECT_EQ(s.found, 0u);
    uint32_t count = 99;
    EXPECT_EQ(ent_scene_contacts(plain.get(), 0, nullptr, &count), ENT_OK) << ent_last_error();
    EXPECT_EQ(count, 0u);

    ScenePtr pressed = bowel_pressed_into_plane(0.002);
    ASSERT_TRUE(pressed);
    EXPECT_GT(summary(pressed.get()).capacity, 0u);
    EXPECT_TRUE(contacts(pressed.get()).empty()) << "no evaluation yet";
}

TEST(Contacts, ABowelPressedIntoAPlaneFeelsThePenaltyLawOnEverySphere) {
    const double depth = 0.002;
    ScenePtr scene = bowel_pressed_into_plane(depth);
    ASSERT_TRUE(scene);
    // One step: its only evaluation is at the start, at rest (implicit Euler), where the
    // damper and friction have no velocity to act on: the force is k d along the normal.
    ASSERT_TRUE(step_n(scene.get(), 1e-4, 1));
    const std::vector<ent_contact> list = contacts(scene.get());
    const ent_contact_summary s = summary(scene.get());
    // Spheres every R / 2 over 0.3 m.
    const uint32_t spheres = static_cast<uint32_t>(std::lround(0.3 / (0.5 * kRadius))) + 1;
    ASSERT_EQ(list.size(), spheres);
    EXPECT_EQ(s.found, spheres);
    EXPECT_EQ(s.listed, spheres);
    EXPECT_EQ(s.obstacle_contacts, spheres);
    EXPECT_EQ(s.self_contacts + s.tool_contacts, 0u);
    for (std::size_t i = 0; i < list.size(); ++i) {
        const ent_contact& c = list[i];
        SCOPED_TRACE(i);
        EXPECT_EQ(c.struct_size, sizeof(ent_contact));
        EXPECT_EQ(c.kind, ENT_CONTACT_OBSTACLE);
        EXPECT_EQ(c.index, 0);
        EXPECT_DOUBLE_EQ(c.u, double(i) / (spheres - 1));
        EXPECT_EQ(c.other_u, -1.0);
        EXPECT_NEAR(c.depth_m, depth, 1e-12);
        EXPECT_NEAR(c.normal[2], 1.0, 1e-15);
        EXPECT_NEAR(c.force_N[0], 0.0, 1e-12);
        EXPECT_NEAR(c.force_N[1], 0.0, 1e-12);
        EXPECT_NEAR(c.force_N[2], kStiffness * depth, 1e-9);
        EXPECT_NEAR(c.point_m[2], 0.0, 1e-12) << "the point is on the plane";
        EXPECT_NEAR(c.point_m[0], -0.15 + 0.3 * c.u, 1e-9);
    }
    EXPECT_NEAR(s.largest_force_N, kStiffness * depth, 1e-9);
    EXPECT_GE(s.largest_force_u, 0.0);
    EXPECT_LE(s.largest_force_u, 1.0);
    // Evenly spaced at the rest length, then pushed up for 0.1 ms: hardly any stretch.
    EXPECT_NEAR(s.largest_stretch, 0.0, 1e-6);
}

TEST(Contacts, FoldsOverlappingAtRestPushApartWithTheirDepth) {
    double length = 0.0;
    const double overlap = 0.003;
    const std::vector<double> points = hairpin(0.2, 2 * kRadius - overlap, 40, &length);
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    desc.length_m = length;
    desc.control_points = 40;
    desc.shape = ENT_SHAPE_POINTS;
    desc.shape_points_xyz_m = points.data();
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    ASSERT_TRUE(step_n(scene.get(), 1e-4, 1));
    const std::vector<ent_contact> list = contacts(scene.get());
    const ent_contact_summary s = summary(scene.get());
    EXPECT_GT(list.size(), 20u) << "the legs overlap along 20 cm";
    EXPECT_EQ(s.self_contacts, list.size());
    double largest = 0.0;
    for (const ent_contact& c : list) {
        EXPECT_EQ(c.kind, ENT_CONTACT_SELF);
        EXPECT_EQ(c.index, -1);
        EXPECT_GT(c.other_u, c.u);
        EXPECT_GT(c.depth_m, 0.0);
        EXPECT_LE(c.depth_m, overlap + 1e-9);
        EXPECT_NEAR(norm3(c.normal), 1.0, 1e-12);
        // At rest: the spring alone, k d along the normal, which pushes the first leg (y = 0,
        // smaller u) away from the second (y > 0).
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(c.force_N[k], kStiffness * c.depth_m * c.normal[k], 1e-12);
        EXPECT_LT(c.normal[1], -0.9);
        EXPECT_NEAR(c.point_m[1], 0.5 * (2 * kRadius - overlap), 2e-3) << "midway between the legs";
        largest = std::max(largest, norm3(c.force_N));
    }
    EXPECT_DOUBLE_EQ(s.largest_force_N, largest);
}

// A bowel on the floor and a vertical tool pushing it sideways (as in test_tools.cpp).
struct Pushed {
    ScenePtr scene;
    int32_t tool = -1;
};

Pushed bowel_and_tool(int32_t mode = ENT_TOOL_MODE_PROXY) {
    Pushed p;
    p.scene = bowel_on_plane(BowelOnPlane{});
    if (!p.scene) return p;
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    tool.position_m[1] = 0.05;
    tool.position_m[2] = kRadius;
    tool.mode = mode;
    EXPECT_EQ(ent_tool_add(p.scene.get(), &tool, &p.tool), ENT_OK) << ent_last_error();
    return p;
}

void check_contacts_add_up_to_minus_the_wrench(int32_t mode) {
    Pushed p = bowel_and_tool(mode);
    ASSERT_TRUE(p.scene);
    const double dt = 1e-3;
    double impulse[3] = {0.0, 0.0, 0.0}, impulse_magnitude = 0.0;
    int touching_steps = 0;
    for (int i = 1; i <= 600; ++i) {
        const double tip[3] = {0.0, 0.05 - 1e-4 * i, kRadius};
        ASSERT_EQ(ent_tool_set_pose(p.scene.get(), p.tool, tip, kIdentity), ENT_OK) << ent_last_error();
        ASSERT_EQ(ent_scene_step(p.scene.get(), dt), ENT_OK) << ent_last_error();
        double force[3], torque[3];
        ASSERT_EQ(ent_tool_wrench(p.scene.get(), p.tool, force, torque), ENT_OK) << ent_last_error();
        // The torque is about the tip in the scene: the proxy's (the default mode).
        ent_tool_feedback feedback;
        std::memset(&feedback, 0, sizeof feedback);
        feedback.struct_size = sizeof feedback;
        ASSERT_EQ(ent_tool_read_feedback(p.scene.get(), p.tool, &feedback), ENT_OK) << ent_last_error();
        const double* proxy = feedback.proxy_position_m;
        // The contact impulse the test adds up itself (no grasp: the wrench is all contact).
        for (int k = 0; k < 3; ++k) impulse[k] += dt * force[k];
        impulse_magnitude += dt * norm3(force);

        double sum[3] = {0.0, 0.0, 0.0}, moment[3] = {0.0, 0.0, 0.0}, largest = 0.0;
        std::vector<double> us;
        for (const ent_contact& c : contacts(p.scene.get())) {
            if (c.kind != ENT_CONTACT_TOOL) continue;
            EXPECT_EQ(c.index, p.tool);
            us.push_back(c.u);
            largest = std::max(largest, norm3(c.force_N));
            for (int k = 0; k < 3; ++k) sum[k] += c.force_N[k];
            // The torque of -f about the proxy's tip, where the tool ends this step.
            const double r[3] = {c.point_m[0] - proxy[0], c.point_m[1] - proxy[1], c.point_m[2] - proxy[2]};
            moment[0] -= r[1] * c.force_N[2] - r[2] * c.force_N[1];
            moment[1] -= r[2] * c.force_N[0] - r[0] * c.force_N[2];
            moment[2] -= r[0] * c.force_N[1] - r[1] * c.force_N[0];
        }
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(sum[k], -force[k], 1e-12 * (1 + norm3(force))) << "step " << i;
            EXPECT_NEAR(moment[k], torque[k], 1e-12 * (1 + norm3(torque))) << "step " << i;
        }
        std::vector<double> ranges(2 * 8);
        const ent_tool_contacts t = tool_contacts(p.scene.get(), p.tool, &ranges);
        EXPECT_EQ(t.contacts, us.size());
        EXPECT_DOUBLE_EQ(t.largest_force_N, largest);
        EXPECT_EQ(t.grasping, 0);
        EXPECT_EQ(t.grasp_u, -1.0);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(t.contact_impulse_Ns[k], impulse[k], 1e-12);
        EXPECT_NEAR(t.contact_impulse_magnitude_Ns, impulse_magnitude, 1e-12);
        // Every u touched lies in one of the ranges, and every range ends at a u touched.
        ASSERT_LE(t.range_count, 8u);
        EXPECT_EQ(t.range_count > 0, !us.empty());
        for (const double u : us) {
            bool inside = false;
            for (uint32_t r = 0; r < t.range_count; ++r) inside |= ranges[2 * r] <= u && u <= ranges[2 * r + 1];
            EXPECT_TRUE(inside) << "u " << u;
        }
        for (uint32_t r = 0; r < t.range_count; ++r) {
            EXPECT_NE(std::find(us.begin(), us.end(), ranges[2 * r]), us.end());
            EXPECT_NE(std::find(us.begin(), us.end(), ranges[2 * r + 1]), us.end());
        }
        touching_steps += us.empty() ? 0 : 1;
    }
    EXPECT_GT(touching_steps, 200);
    EXPECT_GT(impulse_magnitude, 0.01);
    std::cout << "[ tool contacts ] " << (mode == ENT_TOOL_MODE_PROXY ? "proxy" : "direct") << ": touching in "
              << touching_steps << " of 600 steps, contact impulse " << impulse_magnitude << " N s\n";
}

TEST(Contacts, AToolsContactsAddUpToMinusItsWrench) { check_contacts_add_up_to_minus_the_wrench(ENT_TOOL_MODE_PROXY); }

TEST(Contacts, ADirectToolsContactsAddUpToMinusItsWrench) {
    check_contacts_add_up_to_minus_the_wrench(ENT_TOOL_MODE_DIRECT);
}

TEST(Contacts, AGraspSaysWhereItTookHold) {
    Pushed p = bowel_and_tool();
    ASSERT_TRUE(p.scene);
    // The tip over the middle of the bowel (x = 0 is u = 0.5), just touching its side.
    const double tip[3] = {0.0, kRadius + 0.005, kRadius};
    ASSERT_EQ(ent_tool_set_pose(p.scene.get(), p.tool, tip, kIdentity), ENT_OK);
    ASSERT_TRUE(step_n(p.scene.get(), 1e-3, 50));
    ASSERT_EQ(ent_tool_grasp(p.scene.get(), p.tool), ENT_OK);
    ASSERT_TRUE(step_n(p.scene.get(), 1e-3, 1));
    const ent_tool_contacts t = tool_contacts(p.scene.get(), p.tool, nullptr);
    ASSERT_EQ(t.grasping, 1);
    // Spheres every R / 2 = 6.25 mm over 0.4 m: the nearest is within half a spacing of x = 0.
    EXPECT_NEAR(t.grasp_u, 0.5, 0.5 * 0.5 * kRadius / 0.4 + 1e-9);
    ASSERT_EQ(ent_tool_release(p.scene.get(), p.tool), ENT_OK);
    ASSERT_TRUE(step_n(p.scene.get(), 1e-3, 1));
    EXPECT_EQ(tool_contacts(p.scene.get(), p.tool, nullptr).grasp_u, -1.0);
}

TEST(Contacts, AStretchedAxisReportsItsStretch) {
    // Control points evenly spaced at 1.1 times the rest spacing: every segment is 10 % long.
    const uint32_t n = 21;
    const double length = 0.5, spacing = 1.1 * length / (n - 1);
    std::vector<double> points;
    for (uint32_t i = 0; i < n; ++i) points.insert(points.end(), {spacing * i, 0.0, 0.0});
    // Then segment 15 alone longer still: points 16 and on moved 2 mm further along x.
    std::vector<double> local = points;
    for (uint32_t i = 16; i < n; ++i) local[3 * i] += 0.002;
    for (const auto& [shape, expected, where] :
         {std::make_tuple(&points, 0.1, -1.0), std::make_tuple(&local, -1.0, 15.5 / 20.0)}) {
        ent_scene_desc desc = default_desc();
        desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH);
        desc.length_m = length;
        desc.control_points = n;
        desc.shape = ENT_SHAPE_POINTS;
        desc.shape_points_xyz_m = shape->data();
        ScenePtr scene = create(desc);
        ASSERT_TRUE(scene);
        const ent_contact_summary s = summary(scene.get());
        if (expected >= 0.0) {
            EXPECT_NEAR(s.largest_stretch, expected, 1e-9);
        } else {
            EXPECT_GT(s.largest_stretch, 0.1 + 0.002 / (length / (n - 1)) * 0.5) << "segment 15 is the longest";
            EXPECT_NEAR(s.largest_stretch_u, where, 0.01);
        }
    }
}

TEST(Contacts, ABufferTooSmallGetsTheCountAndNothingElse) {
    ScenePtr scene = bowel_pressed_into_plane(0.002);
    ASSERT_TRUE(scene);
    ASSERT_TRUE(step_n(scene.get(), 1e-4, 1));
    uint32_t count = 0;
    ASSERT_EQ(ent_scene_contacts(scene.get(), 0, nullptr, &count), ENT_OK);
    ASSERT_GT(count, 2u);
    std::vector<ent_contact> list(count - 1);
    std::memset(list.data(), 0x5a, list.size() * sizeof(ent_contact));
    list[0].struct_size = sizeof(ent_contact);
    uint32_t got = 0;
    EXPECT_EQ(ent_scene_contacts(scene.get(), count - 1, list.data(), &got), ENT_ERROR_BUFFER_TOO_SMALL);
    EXPECT_EQ(got, count);
    EXPECT_NE(std::string(ent_last_error()).find("capacity"), std::string::npos);
    EXPECT_EQ(list[1].kind, int32_t(0x5a5a5a5a)) << "nothing copied";
}

TEST(Contacts, AStructSizeNoReleaseHasIsRefused) {
    ScenePtr scene = bowel_pressed_into_plane(0.002);
    ASSERT_TRUE(scene);
    ASSERT_TRUE(step_n(scene.get(), 1e-4, 1));
    uint32_t count = 0;
    ASSERT_EQ(ent_scene_contacts(scene.get(), 0, nullptr, &count), ENT_OK);
    std::vector<ent_contact> list(count);
    list[0].struct_size = 12;
    uint32_t got = 12345;
    EXPECT_EQ(ent_scene_contacts(scene.get(), count, list.data(), &got), ENT_ERROR_VERSION);
    EXPECT_EQ(got, 12345u);
    EXPECT_NE(std::string(ent_last_error()).find("struct_size"), std::string::npos);
}

}  // namespace
