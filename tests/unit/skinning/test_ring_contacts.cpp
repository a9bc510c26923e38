// SPDX-License-Identifier: Apache-2.0
// One ring deformed where another fold presses on it (lib/skinning/ring_contacts.h): cut
// to the plane half-way between the axes, its cross-section's area given back by a bounded
// bulge that never crosses that plane; a press too deep for the largest bulge reported
// short; rays kept short of the neighbouring rings on a bend tighter than R.
#include "skinning/ring_contacts.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skinning/axis_samples.h"
#include "skinning/skin_axes.h"
#include "skinning/skin_fixtures.h"
#include "spline/arc_length.h"

namespace {

using namespace skin_test;
using enteron::Vec3;
using enteron::skinning::AxisSamples;
using enteron::skinning::FoldContacts;
using enteron::skinning::kMaxBulgeReach;
using enteron::skinning::RingContacts;

constexpr std::size_t kRays = 64;

struct PressedRing {
    // Legs along x, `gap` apart axis to axis; the ring in the middle of the first leg, its
    // rays in the yz plane from +y (towards the other leg).
    explicit PressedRing(double gap) : points(u_turn_axis(0.2, gap, 0.25 * R)) {
        table.build(points.data(), points.size() / 3);
        samples.build(table, points.data(), points.size() / 3,
                      AxisSamples::intervals_for(table.total_length(), 0.25 * R), 0.0, AxisSamples::Curvature::compute);
        folds.build(samples, R, 1.5 * R);
        for (std::size_t j = 0; j < kRays; ++j) {
            cosine[j] = std::cos(2.0 * kPi * double(j) / kRays);
            sine[j] = std::sin(2.0 * kPi * double(j) / kRays);
        }
        ring.centre = Vec3{-0.1, -0.5 * gap, 0.0};
        ring.normal = Vec3{0.0, 1.0, 0.0};
        ring.binormal = Vec3{0.0, 0.0, -1.0};
        ring.tangent = Vec3{1.0, 0.0, 0.0};
        ring.arc_length = 0.1;
        ring.radius = R;
        ring.cosine = cosine;
        ring.sine = sine;
        ring.rays = kRays;
    }
    // Every ray free at R: deformed into out.
    RingContacts::Result deform() {
        std::fill_n(free, kRays, R);
        return contacts.deform(folds, ring, free, out);
    }
    double area(const double* t) const {
        double sum = 0.0;
        for (std::size_t j = 0; j < kRays; ++j) sum += 0.5 * std::sin(2.0 * kPi / kRays) * t[j] * t[(j + 1) % kRays];
        return sum;
    }
    std::vector<double> points;
    enteron::spline::ArcLengthTable table;
    AxisSamples samples;
    FoldContacts folds;
    double cosine[kRays], sine[kRays];
    RingContacts::Ring ring;
    RingContacts contacts;
    double free[kRays], out[kRays];
};

TEST(RingContacts, APressedRingMeetsTheOtherOnTheMidPlaneAndKeepsItsArea) {
    const double gap = 1.8 * R, half = 0.5 * gap;
    PressedRing pressed(gap);
    const RingContacts::Result result = pressed.deform();
    const double* free = pressed.free;
    const double* out = pressed.out;
    EXPECT_TRUE(result.touched);
    EXPECT_GT(result.bulge_reach, 0.0);
    EXPECT_LT(result.bulge_reach, kMaxBulgeReach);
    EXPECT_EQ(result.short_area, 0.0);
    // The lost segment of the disc beyond the mid-plane: R^2 acos(h / R) - h sqrt(R^2 - h^2),
    // as the 64-gon sees it (within its sag).
    EXPECT_NEAR(result.lost_area, R * R * std::acos(half / R) - half * std::sqrt(R * R - half * half), 0.03 * result.lost_area);
    std::size_t on_plane = 0;
    double highest = 0.0;
    for (std::size_t j = 0; j < kRays; ++j) {
        const double towards = pressed.cosine[j];  // the ray's cosine with +y, towards the other leg
        // Never past the mid-plane; on it where the free circle crossed it.
        EXPECT_LE(out[j] * towards, half * (1.0 + 1e-9)) << j;
        if (R * towards > half) {
            EXPECT_NEAR(out[j] * towards, half, 1e-6 * R) << j;
            ++on_plane;
        } else {
            EXPECT_GE(out[j], R * (1.0 - 1e-12)) << j;  // free rays only swell
            highest = std::max(highest, out[j] - R);
        }
    }
    EXPECT_EQ(on_plane, 2 * std::size_t(std::floor(std::acos(half / R) / (2.0 * kPi / kRays))) + 1);
    // The bulge: there, bounded, and the area back to a thousandth of what was lost.
    EXPECT_GT(highest, 0.001 * R);
    EXPECT_LE(highest, 4.0 * result.bulge_reach / 27.0 * R * (1.0 + 1e-6));
    EXPECT_NEAR(pressed.area(out), pressed.area(free), 2e-3 * result.lost_area);
}

TEST(RingContacts, APressTooDeepForTheLargestBulgeIsReportedShort) {
    const double gap = 1.2 * R, half = 0.5 * gap;
    PressedRing pressed(gap);
    const RingContacts::Result result = pressed.deform();
    const double* free = pressed.free;
    const double* out = pressed.out;
    EXPECT_EQ(result.bulge_reach, kMaxBulgeReach);
    EXPECT_GT(result.short_area, 0.0);
    EXPECT_NEAR(pressed.area(free) - pressed.area(out), result.short_area, 1e-3 * result.lost_area);
    for (std::size_t j = 0; j < kRays; ++j) {
        EXPECT_LE(out[j] * pressed.cosine[j], half * (1.0 + 1e-9)) << j;
        EXPECT_LE(out[j], R * (1.0 + 4.0 * kMaxBulgeReach / 27.0) + 1e-12) << j;
    }
}

TEST(RingContacts, RaysStopShortOfTheNeighbouringRingsOnABendTighterThanR) {
    // Rings on a circle of radius R / 2 around the origin, R / 2 apart along it; nothing else.
    const double rho = 0.5 * R, step = 0.5 * R, angle = step / rho;
    const Vec3 previous{rho * std::cos(-angle), rho * std::sin(-angle), 0.0}, next{rho * std::cos(angle), rho * std::sin(angle), 0.0};
    double cosine[kRays], sine[kRays], free[kRays], out[kRays];
    for (std::size_t j = 0; j < kRays; ++j) {
        cosine[j] = std::cos(2.0 * kPi * double(j) / kRays);
        sine[j] = std::sin(2.0 * kPi * double(j) / kRays);
        free[j] = R;
    }
    RingContacts::Ring ring;
    ring.centre = Vec3{rho, 0.0, 0.0};
    ring.normal = Vec3{-1.0, 0.0, 0.0};  // towards the centre of the bend
    ring.binormal = Vec3{0.0, 0.0, 1.0};
    ring.tangent = Vec3{0.0, 1.0, 0.0};
    ring.radius = R;
    ring.cosine = cosine;
    ring.sine = sine;
    ring.rays = kRays;
    ring.previous_centre = &previous;
    ring.next_centre = &next;
    const FoldContacts none;
    RingContacts contacts;
    EXPECT_FALSE(contacts.deform(none, ring, free, out).touched);
    for (std::size_t j = 0; j < kRays; ++j) {
        if (cosine[j] > 0.0) {
            EXPECT_LT(out[j] * cosine[j], 0.99 * rho * (1.0 + 1e-12)) << j;  // short of the bend's axis
        } else {
            EXPECT_EQ(out[j], R) << j;  // the outer side untouched
        }
    }
}

}  // namespace
