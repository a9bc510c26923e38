// SPDX-License-Identifier: Apache-2.0
// The closest point of a triangle (lib/collision/closest_point_on_triangle.h) against a
// reference written from the geometry: the projection onto the plane when it falls inside,
// otherwise the closest of the three edges' closest points; and the feature it names (a
// corner, an edge, the face) is the one that point lies on.
#include <gtest/gtest.h>

#include <random>

#include "collision/closest_point_on_triangle.h"

namespace enteron::collision {
namespace {

Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    return a + t * (b - a);
}

// The reference: inside test by barycentric coordinates of the projection.
Vec3 reference(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const Vec3 projected = p - ((p - a).dot(n) / n.squaredNorm()) * n;
    const double u = (b - projected).cross(c - projected).dot(n), v = (c - projected).cross(a - projected).dot(n),
                 w = (a - projected).cross(b - projected).dot(n);
    if (u >= 0.0 && v >= 0.0 && w >= 0.0) return projected;
    Vec3 best = closest_on_segment(p, a, b);
    for (const Vec3& candidate : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)})
        if ((p - candidate).squaredNorm() < (p - best).squaredNorm()) best = candidate;
    return best;
}

// Whether `point` lies on `feature` of the triangle (within round-off).
bool lies_on(const Vec3& point, TriangleFeature feature, const Vec3& a, const Vec3& b, const Vec3& c) {
    const double tolerance = 1e-12;
    switch (feature) {
        case TriangleFeature::corner_a: return (point - a).norm() < tolerance;
        case TriangleFeature::corner_b: return (point - b).norm() < tolerance;
        case TriangleFeature::corner_c: return (point - c).norm() < tolerance;
        case TriangleFeature::edge_ab: return (point - closest_on_segment(point, a, b)).norm() < tolerance;
        case TriangleFeature::edge_bc: return (point - closest_on_segment(point, b, c)).norm() < tolerance;
        case TriangleFeature::edge_ca: return (point - closest_on_segment(point, c, a)).norm() < tolerance;
        case TriangleFeature::face: return true;
    }
    return false;
}

TEST(ClosestPointOnTriangle, MatchesTheGeometryAndNamesTheFeature) {
    std::mt19937_64 random(17);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int features[7] = {};
    for (int trial = 0; trial < 20000; ++trial) {
        const Vec3 a(u(random), u(random), u(random)), b(u(random), u(random), u(random)), c(u(random), u(random), u(random));
        if ((b - a).cross(c - a).norm() < 1e-3) continue;  // a sliver: the reference's projection is ill-conditioned
        const Vec3 p = 2.0 * Vec3(u(random), u(random), u(random));
        const TrianglePoint found = closest_point_on_triangle(p, a, b, c);
        const Vec3 expected = reference(p, a, b, c);
        ASSERT_LT((found.point - expected).norm(), 1e-9) << "trial " << trial;
        ASSERT_TRUE(lies_on(found.point, found.feature, a, b, c)) << "trial " << trial;
        features[static_cast<int>(found.feature)] += 1;
    }
    for (int f = 0; f < 7; ++f) EXPECT_GT(features[f], 100) << "feature " << f << " reached";
}

TEST(ClosestPointOnTriangle, EachRegionGivesItsFeature) {
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_EQ(closest_point_on_triangle(Vec3(-1, -1, 2), a, b, c).feature, TriangleFeature::corner_a);
    EXPECT_EQ(closest_point_on_triangle(Vec3(2, -0.5, 0), a, b, c).feature, TriangleFeature::corner_b);
    EXPECT_EQ(closest_point_on_triangle(Vec3(-0.1, 3, 0), a, b, c).feature, TriangleFeature::corner_c);
    EXPECT_EQ(closest_point_on_triangle(Vec3(0.5, -1, 1), a, b, c).feature, TriangleFeature::edge_ab);
    EXPECT_EQ(closest_point_on_triangle(Vec3(1, 1, -1), a, b, c).feature, TriangleFeature::edge_bc);
    EXPECT_EQ(closest_point_on_triangle(Vec3(-1, 0.5, 0), a, b, c).feature, TriangleFeature::edge_ca);
    const TrianglePoint inside = closest_point_on_triangle(Vec3(0.2, 0.3, -0.7), a, b, c);
    EXPECT_EQ(inside.feature, TriangleFeature::face);
    EXPECT_LT((inside.point - Vec3(0.2, 0.3, 0.0)).norm(), 1e-15);
}

}  // namespace
}  // namespace enteron::collision
