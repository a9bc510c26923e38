// SPDX-License-Identifier: Apache-2.0
// The skins where two folds press into each other (contact_profile.h, ring_contacts.h):
// two legs of one tube pushed together (the stand-in for two tubes, issue 28) meet on a
// flat contact patch of the predicted width, with no overlap, a bounded bulge and the
// volume kept; contacts that come and go over a sequence of frames move the surface
// without popping.
#include <gtest/gtest.h>

#include <cmath>

#include "skinning/contact_profile.h"
#include "skinning/skin.h"
#include "skinning/skin_axes.h"
#include "skinning/skin_fixtures.h"
#include "skinning/skin_metrics.h"
#include "spline/catmull_rom.h"

namespace {

using namespace skin_test;
using namespace enteron::skinning;
using enteron::Vec3;

// Legs 3 R apart along x from x = -0.2 m to the turn at x = 0, the second leg's middle
// (x = -0.1 m) pushed towards the first over 6 R either way: `press` = 1.2 R leaves the
// legs 1.8 R apart over the bump's top.
constexpr double kLeg = 0.2, kGap = 3.0 * R, kHalf = 6.0 * R;

std::vector<double> pressed_legs(double press) { return pressed_u_turn_axis(kLeg, kGap, press, kHalf, 0.25 * R); }

SkinSettings with_contacts(SkinMethod method, bool contacts) {
    SkinSettings s = defaults(method);
    s.contact_surfaces = contacts;
    return s;
}

// The volume of the lens where the two legs' tubes of radius R overlap, both halves: the
// area of the circles' overlap, integrated along the bump, m^3.
double lens_volume(double press) {
    double volume = 0.0;
    const int steps = 4000;
    for (int i = 0; i < steps; ++i) {
        const double x = -kHalf + 2.0 * kHalf * (i + 0.5) / steps, c = std::cos(0.5 * kPi * x / kHalf);
        const double h = 0.5 * (kGap - press * c * c);  // half the legs' distance
        if (h < R) volume += 2.0 * (R * R * std::acos(h / R) - h * std::sqrt(R * R - h * h)) * (2.0 * kHalf / steps);
    }
    return volume;
}

TEST(SkinContacts, PressedLegsMeetOnAFlatPatchOfThePredictedWidthWithoutOverlap) {
    const double press = 1.2 * R, half_gap = 0.5 * (kGap - press);  // 0.9 R at the top
    const auto q = pressed_legs(press);
    SkinSettings fine = with_contacts(SkinMethod::convolution, true);
    fine.segments = 128;  // resolves the patch's width to 0.03 R
    auto skin = make_skin(fine);
    const SkinMetrics m = skin_and_measure(*skin, q);
    EXPECT_TRUE(m.watertight);
    EXPECT_EQ(m.inverted_triangles, 0u);
    // The surfaces meet: nothing of one leg inside the other's skin, no gap between them,
    // but for the flat triangles where the contact's rim runs across the rings (R / 2 apart:
    // a chord that long on a surface bending with radius R sags by (R / 2)^2 / (8 R) = 0.03 R).
    EXPECT_LT(m.overlap_depth_max, 0.005);
    EXPECT_EQ(m.overlap_area, 0.0);
    EXPECT_LT(m.contact_gap_max, 0.02);
    EXPECT_GT(m.tube_overlap_depth_max, 0.09);  // pressed half of 0.2 R: the contact is there
    // The patch at the top of the bump (x = -0.1 m): the first leg's vertices on the plane
    // half-way between the legs (y = -R + ... : the legs at y = -1.5 R and y = 0.3 R).
    const double mid_y = 0.5 * (-0.5 * kGap + (0.5 * kGap - press));
    const Mesh& mesh = skin->mesh();
    double patch = 0.0;
    std::size_t on_plane = 0;
    for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
        const double x = mesh.positions[3 * i], y = mesh.positions[3 * i + 1], z = mesh.positions[3 * i + 2];
        if (std::fabs(x + 0.1) > 0.1 * R || y > mid_y + 0.01 * R) continue;  // the first leg at the top only
        if (std::fabs(y - mid_y) < 1e-4 * R) {  // (the bulge leaves the plane tangentially: 1e-3 R a ray on)
            patch = std::max(patch, std::fabs(z));
            ++on_plane;
        }
    }
    // Its half-width: where the free surface (radius R) crosses the plane, sqrt(R^2 - h^2),
    // less at most one ray's step (128 rays: the last ray on the plane).
    const double predicted = std::sqrt(R * R - half_gap * half_gap);
    const double step = half_gap * (std::tan(std::acos(half_gap / R)) - std::tan(std::acos(half_gap / R) - 2.0 * kPi / 128));
    EXPECT_GT(on_plane, 10u);
    EXPECT_LE(patch, predicted * 1.002);
    EXPECT_GE(patch, predicted - step);
    // Without contact surfaces the legs pass through each other by 0.1 R each.
    auto through = make_skin(with_contacts(SkinMethod::convolution, false));
    const SkinMetrics t = skin_and_measure(*through, q);
    EXPECT_GT(t.overlap_depth_max, 0.15);
    EXPECT_GT(t.overlap_area, 0.0);
}

TEST(SkinContacts, TheBulgeIsBoundedAndGivesTheVolumeBack) {
    const double press = 1.2 * R;
    const auto q = pressed_legs(press);
    const double lens = lens_volume(press);
    // The convolution: the cut and the bulge keep the volume of the surfaces passing through
    // each other (which the divergence theorem counts whole), to a small part of the lens.
    auto on = make_skin(with_contacts(SkinMethod::convolution, true));
    auto off = make_skin(with_contacts(SkinMethod::convolution, false));
    const SkinMetrics with = skin_and_measure(*on, q), without = skin_and_measure(*off, q);
    EXPECT_NEAR(with.volume, without.volume, 0.02 * lens);
    EXPECT_LT(std::fabs(with.shape_volume_error), 0.002);
    // The bulge: the surface swells beside the contact, at most 4 w / 27 of R for the
    // largest reach w (contact_profile.h), never more.
    double highest = 0.0;
    const Mesh& mesh = on->mesh();
    const auto& table = on->arc_length();
    for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
        const Vec3 a = enteron::spline::evaluate(
            on->axis_points(), enteron::spline::weights_at(on->axis_count(), table.parameter_at(mesh.u[i] * table.total_length()),
                                                           enteron::spline::Derivative::value));
        const Vec3 v{mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]};
        highest = std::max(highest, (v - a).norm() / R - 1.0);
    }
    EXPECT_GT(highest, 0.01);
    EXPECT_LT(highest, 4.0 * kMaxBulgeReach / 27.0 + 0.005);  // and the skin's radius error
    // The point skeleton draws the union of the legs (its field switches between them on
    // the contact surface): the union lacks the lens, which the bulge gives back.
    auto union_bulged = make_skin(with_contacts(SkinMethod::point_skeleton, true));
    auto union_plain = make_skin(with_contacts(SkinMethod::point_skeleton, false));
    const SkinMetrics bulged = skin_and_measure(*union_bulged, q), plain = skin_and_measure(*union_plain, q);
    EXPECT_NEAR(bulged.volume - plain.volume, lens, 0.2 * lens);
    EXPECT_LT(bulged.overlap_depth_max, 0.02);
    EXPECT_TRUE(bulged.watertight);
}

TEST(SkinContacts, ContactsComeAndGoWithoutPopping) {
    // The bump pushes the second leg into the first and back, 0.02 R a frame: a contact
    // appears, deepens to 0.3 R of pressing and goes. No vertex may move more than the
    // axis under it by more than twice a frame's push (the contact surface moves half of
    // it, the bulge less): a jump of the contact or of the bulge would show.
    const double step = 0.02 * R;
    for (SkinMethod method : {SkinMethod::convolution, SkinMethod::tube}) {
        auto skin = make_skin(defaults(method));
        double worst = 0.0, deepest = 0.0;
        for (int frame = 0; frame <= 160; ++frame) {
            const double press = step * (frame <= 80 ? frame : 160 - frame);
            const auto q = pressed_legs(press);
            skin->update(q.data(), q.size() / 3);
            if (frame == 0) continue;
            PreviousFrame previous;
            previous.mesh = &skin->previous_mesh();
            previous.points_xyz = skin->previous_axis_points();
            previous.count = skin->previous_axis_count();
            previous.table = &skin->previous_arc_length();
            ASSERT_TRUE(skin->same_vertices_as_previous());
            const SkinMetrics m =
                measure_skin(skin->mesh(), skin->axis_points(), skin->axis_count(), skin->arc_length(), R, &previous);
            worst = std::max(worst, m.vertex_excess_motion_max);
            deepest = std::max(deepest, m.tube_overlap_depth_max);
            if (method == SkinMethod::convolution) {
                ASSERT_LT(m.overlap_depth_max, 0.01) << "frame " << frame;
            }
        }
        EXPECT_GT(deepest, 0.25);
        EXPECT_LT(worst * R, 2.0 * step) << int(method);
    }
}

}  // namespace
