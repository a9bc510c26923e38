// SPDX-License-Identifier: Apache-2.0
// A fan or paddle retractor (ent_tool_desc blade_width_m, blade_length_m): its flat blade
// meets the bowel along its whole width, so that pressed on a tube it spreads its force
// over the spheres under it, swept sideways it pushes a front as wide as itself, and, a
// proxy, it never passes through the tube however far the device goes.
#include "capi_scenes.h"

#include <algorithm>
#include <iostream>

#include "test_helpers.h"

using namespace capi_test;

namespace {

using enteron_test::kIdentity;

constexpr double kBladeWidth = 0.06;  // m, along the tube (the tool's local x is world x)

// A 0.8 m bowel along x on the floor, settled, and a vertical tool at `tip` (proxy mode),
// with a blade 6 cm wide and 3 cm long or none.
struct RetractorScene {
    ScenePtr scene;
    int32_t tool = -1;
};

RetractorScene retractor_on_bowel(const double tip[3], bool blade, double bend_stiffness = 2.5e-3) {
    ent_scene_desc desc = default_desc();
    desc.length_m = 0.8;
    desc.control_points = 65;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_center_m[0] = -0.4;
    desc.shape_center_m[2] = kBowelRadius;
    desc.bend_stiffness_N_m2 = bend_stiffness;
    RetractorScene made;
    made.scene = create(desc);
    if (!made.scene) return made;
    ent_obstacle_desc plane;
    ent_obstacle_desc_default(&plane);
    plane.kind = ENT_OBSTACLE_PLANE;
    EXPECT_EQ(ent_scene_add_obstacle(made.scene.get(), &plane, nullptr), ENT_OK) << ent_last_error();
    EXPECT_TRUE(step_n(made.scene.get(), 1e-3, 100));  // settle
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    if (blade) {
        tool.blade_width_m = kBladeWidth;
        tool.blade_length_m = 0.03;
    }
    for (int c = 0; c < 3; ++c) tool.position_m[c] = tip[c];
    EXPECT_EQ(ent_tool_add(made.scene.get(), &tool, &made.tool), ENT_OK) << ent_last_error();
    return made;
}

// Moves the commanded tip from `from` to `to` in `steps` steps of 1 ms; the deepest the
// proxy's tip came below `floor_z` (m, 0: never) and the most spheres it touched.
struct Drive {
    double deepest = 0.0;
    uint32_t most_contacts = 0;
};
Drive drive_tip(const RetractorScene& r, const double from[3], const double to[3], int steps, double floor_z) {
    Drive drive;
    for (int i = 1; i <= steps; ++i) {
        const double a = static_cast<double>(i) / steps;
        const double p[3] = {(1 - a) * from[0] + a * to[0], (1 - a) * from[1] + a * to[1], (1 - a) * from[2] + a * to[2]};
        EXPECT_EQ(ent_tool_set_pose(r.scene.get(), r.tool, p, kIdentity), ENT_OK) << ent_last_error();
        if (ent_scene_step(r.scene.get(), 1e-3) != ENT_OK) {
            ADD_FAILURE() << "step " << i << ": " << ent_last_error();
            return drive;
        }
        ent_tool_feedback feedback{};
        feedback.struct_size = sizeof feedback;
        EXPECT_EQ(ent_tool_read_feedback(r.scene.get(), r.tool, &feedback), ENT_OK) << ent_last_error();
        drive.deepest = std::max(drive.deepest, floor_z - feedback.proxy_position_m[2]);
        drive.most_contacts = std::max(drive.most_contacts, feedback.contacts);
    }
    return drive;
}

// How much less than the middle (x = 0) the control points 2.5 cm either side moved in y:
// the sag of the front the tool pushed, m.
double front_sag(const std::vector<double>& before, const std::vector<double>& after) {
    double middle = 0.0, sides = 0.0;
    int side_count = 0;
    for (std::size_t i = 0; i + 2 < before.size(); i += 3) {
        const double moved = after[i + 1] - before[i + 1];
        if (std::fabs(before[i]) < 1e-6) middle = moved;
        if (std::fabs(std::fabs(before[i]) - 0.025) < 1e-6) {
            sides += moved;
            ++side_count;
        }
    }
    return side_count == 2 ? middle - 0.5 * sides : 1.0;
}

}  // namespace

TEST(Retractor, PressedOnTheTubeTheBladeSpreadsItsForceAndStaysOnTop) {
    // From 3 cm above the tube's top to 3 cm into it, in 0.3 s: max_force (5 N) holds it.
    const double above[3] = {0.0, 0.0, 2 * kBowelRadius + 0.03}, into[3] = {0.0, 0.0, 2 * kBowelRadius - 0.03};
    const double floor_z = 2 * kBowelRadius - 0.5 * kBowelRadius;  // half a radius into the tube's top
    uint32_t contacts[2] = {0, 0};
    for (int blade = 0; blade < 2; ++blade) {
        RetractorScene r = retractor_on_bowel(above, blade == 1);
        ASSERT_TRUE(r.scene);
        const Drive pressed = drive_tip(r, above, into, 300, floor_z);
        const Drive held = drive_tip(r, into, into, 200, floor_z);
        contacts[blade] = std::max(pressed.most_contacts, held.most_contacts);
        std::cout << "[ retractor " << (blade ? "blade" : "capsule") << " ] most contacts " << contacts[blade]
                  << ", deepest below half a radius into the tube " << std::max(pressed.deepest, held.deepest) << " m\n";
        // The tool's surface (its radius below the tip) stays above the axis: never through.
        EXPECT_LE(std::max(pressed.deepest, held.deepest), 0.0) << (blade ? "blade" : "capsule");
    }
    // Spheres every R/2 = 6.25 mm: the 6 cm blade spans about ten more than the capsule.
    EXPECT_GE(contacts[1], contacts[0] + 6) << "the blade presses along its width";
}

TEST(Retractor, SweptSidewaysTheBladePushesAFlatFront) {
    // A floppy bowel (EI 2.5e-4 N m^2) pushed from 5 cm beside it to 3 cm past its axis, at
    // 0.1 m/s along the floor: a capsule bends it round itself, the 6 cm blade carries a
    // flat front as wide as itself (control points every 1.25 cm).
    const double beside[3] = {0.0, -0.05, kBowelRadius}, past[3] = {0.0, 0.03, kBowelRadius};
    double sag[2] = {0.0, 0.0};
    for (int blade = 0; blade < 2; ++blade) {
        RetractorScene r = retractor_on_bowel(beside, blade == 1, 2.5e-4);
        ASSERT_TRUE(r.scene);
        const std::vector<double> before = control_points(r.scene.get());
        drive_tip(r, beside, past, 800, 1.0);
        sag[blade] = front_sag(before, control_points(r.scene.get()));
        std::cout << "[ retractor " << (blade ? "blade" : "capsule") << " ] the front 2.5 cm either side of the middle "
                  << "moved " << sag[blade] * 1e3 << " mm less than the middle\n";
    }
    EXPECT_GT(sag[0], 0.002) << "the capsule bends the tube round itself";
    EXPECT_LT(sag[1], 0.6 * sag[0]) << "the blade pushes a flatter front";
}
