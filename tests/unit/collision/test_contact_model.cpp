// SPDX-License-Identifier: Apache-2.0
// The penalty contact law (lib/collision/contact_model.h): it never pulls, damps only
// while the surfaces approach, and its friction opposes sliding within the Coulomb bound.
#include "collision/contact_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using enteron::Vec3;
using enteron::collision::contact_force;
using enteron::collision::ContactForce;
using enteron::collision::ContactParameters;

// A unit normal not along any axis, and velocities made of normal and tangential parts.
const Vec3 kNormal(2 / 7.0, 3 / 7.0, 6 / 7.0);

const Vec3 kTangent(3 / 7.0, -6 / 7.0, 2 / 7.0);  // unit, orthogonal to kNormal

Vec3 velocity(double normal_speed, double tangential_speed) {
    return normal_speed * kNormal + tangential_speed * kTangent;
}

TEST(ContactForce, NeverPulls) {
    const ContactParameters p;  // 500 N/m, 0.5 N s/m
    const double depth = 0.001;
    // Separating fast: a damper on the whole normal speed would give 500 * 0.001 - 0.5 * 10
    // = -4.5 N, a pull; the law keeps the spring alone.
    for (double vn : {0.0, 0.1, 1.0, 10.0, 1e3}) {
        Vec3 v = velocity(vn, 0.05);
        const ContactForce f = contact_force(p, depth, kNormal, v);
        EXPECT_GE(f.normal_force, 0.0) << vn;
        EXPECT_GE(f.force.dot(kNormal), 0.0) << vn;
        EXPECT_NEAR(f.normal_force, p.stiffness * depth, 1e-12) << vn;
        EXPECT_NEAR(f.force.dot(kNormal), f.normal_force, 1e-12) << vn;
        EXPECT_EQ(f.damping, 0.0) << vn;
    }
}

TEST(ContactForce, DampsOnlyWhileApproaching) {
    const ContactParameters p;
    const double depth = 0.002;
    Vec3 v = velocity(-0.4, 0.0);  // approaching at 0.4 m/s
    ContactForce f = contact_force(p, depth, kNormal, v);
    EXPECT_NEAR(f.normal_force, p.stiffness * depth + p.damping * 0.4, 1e-12);
    EXPECT_EQ(f.damping, p.damping);
    EXPECT_EQ(f.stiffness, p.stiffness);
    v = velocity(+0.4, 0.0);  // separating at the same speed
    f = contact_force(p, depth, kNormal, v);
    EXPECT_NEAR(f.normal_force, p.stiffness * depth, 1e-12);
    EXPECT_EQ(f.damping, 0.0);
}

TEST(ContactForce, FrictionOpposesSlidingAndIsBoundedByCoulomb) {
    ContactParameters p;
    p.friction = 0.4;
    p.slip_speed = 0.01;
    const double depth = 0.003;
    for (double vn : {-0.2, 0.0, 0.3})
        for (double vt : {-5.0, -0.3, -0.01, -1e-4, 1e-4, 0.002, 0.01, 0.1, 2.0}) {
            Vec3 v = velocity(vn, vt);
            const ContactForce f = contact_force(p, depth, kNormal, v);
            const double fn = f.force.dot(kNormal);
            const Vec3 tangential = f.force - fn * kNormal;
            const double ft = tangential.dot(kTangent);
            // Along the sliding direction only, against it, at most mu f_n.
            EXPECT_NEAR(tangential.norm(), std::fabs(ft), 1e-12);
            EXPECT_LT(ft * vt, 0.0) << vn << " " << vt;
            EXPECT_LE(std::fabs(ft), p.friction * f.normal_force * (1.0 + 1e-12)) << vn << " " << vt;
            // Fast sliding: nearly the full Coulomb force; slow: viscous, about mu f_n vt / slip.
            if (std::fabs(vt) >= 100 * p.slip_speed) {
                EXPECT_GT(std::fabs(ft), 0.999 * p.friction * f.normal_force) << vn << " " << vt;
            }
            if (std::fabs(vt) <= 0.01 * p.slip_speed) {
                const double viscous = p.friction * f.normal_force * std::fabs(vt) / p.slip_speed;
                EXPECT_NEAR(std::fabs(ft), viscous, 1e-3 * viscous) << vn << " " << vt;
            }
        }
    // Without friction there is no tangential force at all.
    p.friction = 0.0;
    Vec3 v = velocity(-0.1, 1.0);
    const ContactForce f = contact_force(p, depth, kNormal, v);
    EXPECT_NEAR(f.force.dot(kTangent), 0.0, 1e-15);
}

}  // namespace
