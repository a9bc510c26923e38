// SPDX-License-Identifier: Apache-2.0
// The contact law along a ray (lib/skinning/contact_profile.h): D is the contact surface
// inside the other fold, a bounded C1 bulge beside it, nothing beyond; the ray solves
// reproduce the composition u = D(x0 + G u).
#include "skinning/contact_profile.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using enteron::skinning::contact_deformation;
using enteron::skinning::ContactRay;
using enteron::skinning::kMaxBulgeReach;

TEST(ContactProfile, ContactInsideBoundedC1BulgeBesideNothingBeyond) {
    for (double w : {0.05, 0.3, kMaxBulgeReach}) {
        double slope = 0.0;
        // Inside the other fold: the contact surface itself, x.
        EXPECT_EQ(contact_deformation(-0.2, w, &slope), -0.2);
        EXPECT_EQ(slope, 1.0);
        // C1 at x = 0 (slope 1 on both sides) and at x = w (value and slope 0).
        EXPECT_NEAR(contact_deformation(1e-9, w, &slope), 1e-9, 1e-15);
        EXPECT_NEAR(slope, 1.0, 1e-6);
        EXPECT_NEAR(contact_deformation(w * (1.0 - 1e-7), w, &slope), 0.0, 1e-12);
        EXPECT_NEAR(slope, 0.0, 1e-6);
        EXPECT_EQ(contact_deformation(w * 1.5, w, &slope), 0.0);
        // The bulge: never past the contact surface (D <= x), at most 4 w / 27, at x = w / 3.
        double highest = 0.0;
        for (int i = 1; i < 1000; ++i) {
            const double x = w * i / 1000.0;
            const double d = contact_deformation(x, w, &slope);
            EXPECT_LE(d, x);
            EXPECT_GE(d, 0.0);
            highest = std::max(highest, d);
        }
        EXPECT_NEAR(highest, 4.0 * w / 27.0, 1e-6 * w);
        EXPECT_NEAR(contact_deformation(w / 3.0, w, &slope), 4.0 * w / 27.0, 1e-12);
    }
}

TEST(ContactProfile, RaySolvesTheCompositionOnItsLinearModel) {
    // Inside: u = x0 + G u, the contact surface on the ray.
    const ContactRay inside{-0.1, -0.5};
    EXPECT_TRUE(inside.touches());
    const double u = inside.contact_u();
    EXPECT_NEAR(u, inside.x0 + inside.G * u, 1e-15);
    // Beside the contact: u = D(x0 + G u) to a thousandth of the bulge after two Newton steps.
    for (double G : {-1.0, -0.3, 0.0, 0.4}) {
        const ContactRay beside{0.05, G};
        EXPECT_FALSE(beside.touches());
        const double w = 0.4;
        const double b = beside.bulge_u(w);
        double slope = 0.0;
        EXPECT_NEAR(b, contact_deformation(beside.x0 + G * b, w, &slope), 1e-3 * b) << G;
        EXPECT_GT(b, 0.0);
        // A bulge that does not reach the ray: nothing.
        EXPECT_EQ(beside.bulge_u(0.04), 0.0);
        EXPECT_EQ((ContactRay{0.5, G}.bulge_u(0.4)), 0.0);
        // The farther the bulge reaches, the higher it is here.
        EXPECT_GT(beside.bulge_u(0.6), b);
    }
}

}  // namespace
