// SPDX-License-Identifier: Apache-2.0
// The contacts each obstacle of lib/collision/obstacle.h reports for a sphere: depth and
// unit normal, for box walls and corners, planes, spheres and capsules.
#include "collision/obstacle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace {

using enteron::Vec3;
using enteron::collision::for_each_contact;
using enteron::collision::Obstacle;
using enteron::collision::ObstacleContact;
using enteron::collision::ObstacleKind;

std::vector<ObstacleContact> contacts_of(const Obstacle& o, const Vec3& p, double r) {
    std::vector<ObstacleContact> out;
    for_each_contact(o, p, r, [&](const ObstacleContact& c) { out.push_back(c); });
    return out;
}

void expect_normal(const ObstacleContact& c, double x, double y, double z, double tolerance = 1e-12) {
    EXPECT_NEAR(c.normal[0], x, tolerance);
    EXPECT_NEAR(c.normal[1], y, tolerance);
    EXPECT_NEAR(c.normal[2], z, tolerance);
}

Obstacle obstacle_box(double cx, double cy, double cz, double hx, double hy, double hz) {
    Obstacle o;
    o.kind = ObstacleKind::box_inside;
    o.center = {cx, cy, cz};
    o.extent = {hx, hy, hz};
    return o;
}

TEST(Obstacle, BoxInsideWallsAndCorner) {
    const Obstacle o = obstacle_box(1.0, 2.0, 3.0, 0.1, 0.2, 0.3);
    const double r = 0.01;
    // Well inside: nothing. Touching a wall exactly: nothing (depth 0).
    const Vec3 inside(1.0, 2.0, 3.0);
    EXPECT_TRUE(contacts_of(o, inside, r).empty());
    const Vec3 touching(1.09, 2.0, 3.0);
    EXPECT_TRUE(contacts_of(o, touching, r).empty());
    // One wall, the low z one: the sphere reaches 0.004 below the floor.
    const Vec3 floor(1.0, 2.0, 3.0 - 0.3 + 0.006);
    auto c = contacts_of(o, floor, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.004, 1e-12);
    expect_normal(c[0], 0, 0, 1);
    // A centre beyond the wall is deeper than R, pushed back the same way.
    const Vec3 beyond(1.0 - 0.1 - 0.002, 2.0, 3.0);
    c = contacts_of(o, beyond, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.012, 1e-12);
    expect_normal(c[0], 1, 0, 0);
    // A corner (high x, low y, high z): three contacts, one per wall, each with its depth.
    const Vec3 corner(1.0 + 0.096, 2.0 - 0.197, 3.0 + 0.292);
    c = contacts_of(o, corner, r);
    ASSERT_EQ(c.size(), 3u);
    std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.depth < b.depth; });
    EXPECT_NEAR(c[0].depth, 0.002, 1e-12);
    expect_normal(c[0], 0, 0, -1);
    EXPECT_NEAR(c[1].depth, 0.006, 1e-12);
    expect_normal(c[1], -1, 0, 0);
    EXPECT_NEAR(c[2].depth, 0.007, 1e-12);
    expect_normal(c[2], 0, 1, 0);
}

TEST(Obstacle, Plane) {
    Obstacle o;
    o.kind = ObstacleKind::plane;
    o.center = {1.0, 2.0, 3.0};
    o.extent = {0.0, 0.6, 0.8};  // unit, as the environment stores it
    const double r = 0.01;
    // A point 0.004 from the plane on the normal's side, moved along the plane too.
    const Vec3 along(0.5, 0.8, -0.6);  // in the plane: along . n = 0
    const Vec3 near(1.0 + along[0] + 0.004 * 0.0, 2.0 + along[1] + 0.004 * 0.6,
                            3.0 + along[2] + 0.004 * 0.8);
    auto c = contacts_of(o, near, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.006, 1e-12);
    expect_normal(c[0], 0, 0.6, 0.8);
    // Behind the plane: deeper than R, still pushed toward the normal's side.
    const Vec3 behind(1.0, 2.0 - 0.003 * 0.6, 3.0 - 0.003 * 0.8);
    c = contacts_of(o, behind, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.013, 1e-12);
    expect_normal(c[0], 0, 0.6, 0.8);
    // Farther than R on the free side: nothing.
    const Vec3 away(1.0, 2.0 + 0.011 * 0.6, 3.0 + 0.011 * 0.8);
    EXPECT_TRUE(contacts_of(o, away, r).empty());
}

TEST(Obstacle, Sphere) {
    Obstacle o;
    o.kind = ObstacleKind::sphere;
    o.center = {0.1, 0.2, 0.3};
    o.radius = 0.05;
    const double r = 0.01;
    // 0.056 from the centre along (2, -1, 2) / 3: depth 0.05 + 0.01 - 0.056 = 0.004.
    const Vec3 p(0.1 + 0.056 * 2 / 3.0, 0.2 - 0.056 / 3.0, 0.3 + 0.056 * 2 / 3.0);
    auto c = contacts_of(o, p, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.004, 1e-12);
    expect_normal(c[0], 2 / 3.0, -1 / 3.0, 2 / 3.0);
    const Vec3 apart(0.1, 0.2, 0.3 + 0.0601);
    EXPECT_TRUE(contacts_of(o, apart, r).empty());
}

TEST(Obstacle, CapsuleInteriorEndsAndAxis) {
    Obstacle o;
    o.kind = ObstacleKind::capsule;
    o.center = {0.0, 0.0, 0.0};   // start
    o.extent = {0.0, 0.2, 0.0};   // end
    o.radius = 0.03;
    const double r = 0.01;
    // Beside the middle of the axis, 0.035 away along (0.6, 0, -0.8): depth 0.005.
    const Vec3 side(0.035 * 0.6, 0.13, -0.035 * 0.8);
    auto c = contacts_of(o, side, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.005, 1e-12);
    expect_normal(c[0], 0.6, 0.0, -0.8);
    // Beyond the end cap: measured from the end point, along (0, 0.8, 0.6).
    const Vec3 past_end(0.0, 0.2 + 0.032 * 0.8, 0.032 * 0.6);
    c = contacts_of(o, past_end, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.008, 1e-12);
    expect_normal(c[0], 0.0, 0.8, 0.6);
    // Before the start cap, straight along the axis.
    const Vec3 before_start(0.0, -0.037, 0.0);
    c = contacts_of(o, before_start, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.003, 1e-12);
    expect_normal(c[0], 0.0, -1.0, 0.0);
    // Beside the axis but farther than radius + r: nothing; near the end, off the cap: nothing.
    const Vec3 apart(0.0401, 0.1, 0.0);
    EXPECT_TRUE(contacts_of(o, apart, r).empty());
    const Vec3 off_cap(0.03, 0.2 + 0.03, 0.0);  // 0.0424 from the end point
    EXPECT_TRUE(contacts_of(o, off_cap, r).empty());
    // A centre on the axis: full depth, and some unit normal, never NaN.
    const Vec3 on_axis(0.0, 0.07, 0.0);
    c = contacts_of(o, on_axis, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.04, 1e-12);
    EXPECT_NEAR(c[0].normal.norm(), 1.0, 1e-12);
    // The same at the centre of a sphere obstacle.
    Obstacle s;
    s.kind = ObstacleKind::sphere;
    s.center = {0.0, 0.07, 0.0};
    s.radius = 0.03;
    c = contacts_of(s, on_axis, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.04, 1e-12);
    EXPECT_NEAR(c[0].normal.norm(), 1.0, 1e-12);
}

}  // namespace
