// SPDX-License-Identifier: Apache-2.0
// The closest triangle through Embree's hierarchy (lib/collision/triangle_bvh.h) against
// every triangle tried: the same distance to round-off, a closest point on the triangle it
// names, near and far from a sphere, inside a cavity and with a bound that is not the
// answer's; degenerate triangles never answer.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "collision/mesh_fixtures.h"
#include "collision/triangle_bvh.h"

namespace enteron::collision {
namespace {

using collision_test::brute_force_closest;
using collision_test::to_triangle_mesh;

void expect_same_as_brute_force(const TriangleMesh& mesh, double spread, int trials, uint64_t seed) {
    const MeshTopology topology(mesh, std::pmr::new_delete_resource());
    const TriangleBvh bvh(mesh, topology);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < trials; ++trial) {
        const Vec3 p(spread * u(random), spread * u(random), spread * u(random));
        const auto expected = brute_force_closest(mesh, p);
        const TriangleBvh::Closest found = bvh.closest(p, std::numeric_limits<double>::infinity());
        ASSERT_NEAR(found.distance, expected.distance, 1e-12) << p.transpose();
        ASSERT_NEAR((p - found.point.point).norm(), found.distance, 1e-12);
        const auto on_its_triangle = closest_point_on_triangle(p, mesh.corner(found.triangle, 0), mesh.corner(found.triangle, 1),
                                                               mesh.corner(found.triangle, 2));
        ASSERT_LT((on_its_triangle.point - found.point.point).norm(), 1e-12);
        // A bound above the answer finds it too.
        ASSERT_NEAR(bvh.closest(p, 1.5 * expected.distance + 1e-6).distance, expected.distance, 1e-12);
    }
}

TEST(TriangleBvh, FindsTheClosestTriangleOfASphereNearAndFar) {
    const double c[3] = {0.01, -0.02, 0.03};
    const TriangleMesh sphere = to_triangle_mesh(test_meshes::icosphere(c, 0.05, 3));
    expect_same_as_brute_force(sphere, 0.07, 500, 1);
    expect_same_as_brute_force(sphere, 1.0, 200, 2);
}

TEST(TriangleBvh, FindsTheClosestWallOfACavity) {
    const double c[3] = {0, 0, 0}, h[3] = {0.15, 0.2, 0.1};
    expect_same_as_brute_force(to_triangle_mesh(test_meshes::box(c, h, true)), 0.15, 500, 3);
}

TEST(TriangleBvh, ADegenerateTriangleNeverAnswers) {
    TriangleMesh mesh;
    mesh.vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.2, 1.0, 0.3, 0.3, 1.0, 0.4, 0.4, 1.0};
    mesh.indices = {0, 1, 2, 3, 4, 5};  // the second: three points on a line, just above the query
    const MeshTopology topology(mesh, std::pmr::new_delete_resource());
    const TriangleBvh bvh(mesh, topology);
    const TriangleBvh::Closest found = bvh.closest(Vec3(0.3, 0.3, 1.1), std::numeric_limits<double>::infinity());
    EXPECT_EQ(found.triangle, 0u);
    EXPECT_NEAR(found.distance, 1.1, 1e-12);
}

}  // namespace
}  // namespace enteron::collision
