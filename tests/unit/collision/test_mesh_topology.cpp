// SPDX-License-Identifier: Apache-2.0
// A mesh's connectivity and pseudo-normals (lib/collision/mesh_topology.h): a closed box
// and sphere are closed, with their volumes; a cavity's volume is negative; an open sheet,
// a fin on a shared edge, a flipped triangle and a degenerate one are counted as such; the
// pseudo-normals are the face's normal, the sum of an edge's two, and a corner's
// angle-weighted sum; and, the property they exist for, the sign of (p - closest) . n
// tells inside from outside for points near and far, at corners and edges included
// (Baerentzen and Aanaes 2005).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "collision/mesh_fixtures.h"
#include "collision/mesh_topology.h"

namespace enteron::collision {
namespace {

using collision_test::brute_force_closest;
using collision_test::to_triangle_mesh;
std::pmr::memory_resource* const kMeshTopologyMemory = std::pmr::new_delete_resource();
const double kCenter[3] = {0.0, 0.0, 0.0};
const double kHalf[3] = {0.04, 0.03, 0.02};

TEST(MeshTopology, ClosedMeshesAreClosedWithTheirVolumes) {
    const TriangleMesh box = to_triangle_mesh(test_meshes::box(kCenter, kHalf, false));
    const MeshTopology box_topology(box, kMeshTopologyMemory);
    EXPECT_TRUE(box_topology.report().closed());
    EXPECT_NEAR(box_topology.report().signed_volume, 8.0 * kHalf[0] * kHalf[1] * kHalf[2], 1e-15);
    const TriangleMesh cavity = to_triangle_mesh(test_meshes::box(kCenter, kHalf, true));
    const MeshTopology cavity_topology(cavity, kMeshTopologyMemory);
    EXPECT_TRUE(cavity_topology.report().closed());
    EXPECT_NEAR(cavity_topology.report().signed_volume, -8.0 * kHalf[0] * kHalf[1] * kHalf[2], 1e-15);
    const TriangleMesh sphere = to_triangle_mesh(test_meshes::icosphere(kCenter, 0.05, 3));
    const MeshTopology sphere_topology(sphere, kMeshTopologyMemory);
    EXPECT_TRUE(sphere_topology.report().closed());
    const double ball = 4.0 / 3.0 * kPi * std::pow(0.05, 3);
    EXPECT_LT(sphere_topology.report().signed_volume, ball);
    EXPECT_GT(sphere_topology.report().signed_volume, 0.98 * ball) << "an inscribed polyhedron, 1280 faces";
}

TEST(MeshTopology, OpenNonManifoldFlippedAndDegenerateAreCounted) {
    TriangleMesh sheet;  // a square of two triangles
    sheet.vertices = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    sheet.indices = {0, 1, 2, 0, 2, 3};
    const MeshTopology open(sheet, kMeshTopologyMemory);
    EXPECT_EQ(open.report().open_edges, 4u);
    EXPECT_FALSE(open.report().closed());
    TriangleMesh fin = sheet;  // a third triangle on the diagonal, standing up
    fin.vertices.insert(fin.vertices.end(), {0.5, 0.5, 1.0});
    fin.indices.insert(fin.indices.end(), {0, 2, 4});
    EXPECT_EQ(MeshTopology(fin, kMeshTopologyMemory).report().nonmanifold_edges, 1u);
    TriangleMesh flipped = to_triangle_mesh(test_meshes::box(kCenter, kHalf, false));
    std::swap(flipped.indices[1], flipped.indices[2]);
    EXPECT_EQ(MeshTopology(flipped, kMeshTopologyMemory).report().flipped_edges, 3u) << "its three edges";
    TriangleMesh degenerate = sheet;
    degenerate.vertices.insert(degenerate.vertices.end(), {2, 0, 0});
    degenerate.indices.insert(degenerate.indices.end(), {0, 1, 4});  // three points on a line
    const MeshTopology with_sliver(degenerate, kMeshTopologyMemory);
    EXPECT_EQ(with_sliver.report().degenerate_triangles, 1u);
    EXPECT_FALSE(with_sliver.usable(2));
    EXPECT_TRUE(with_sliver.usable(0));
}

TEST(MeshTopology, PseudoNormalsOfAFaceAnEdgeAndACorner) {
    const TriangleMesh box = to_triangle_mesh(test_meshes::box(kCenter, kHalf, false));
    const MeshTopology topology(box, kMeshTopologyMemory);
    // Beyond the +x face's middle, its edge with +y, and the (+,+,+) corner.
    const struct {
        Vec3 p;
        Vec3 direction;
    } cases[] = {{Vec3(0.1, 0.0, 0.0), Vec3(1, 0, 0)},
                 {Vec3(0.1, 0.1, 0.0), Vec3(1, 1, 0).normalized()},
                 {Vec3(0.1, 0.1, 0.1), Vec3(1, 1, 1).normalized()}};
    for (const auto& c : cases) {
        const auto closest = brute_force_closest(box, c.p);
        const Vec3 n = topology.pseudo_normal(closest.triangle, closest.point.feature);
        EXPECT_LT((n.normalized() - c.direction).norm(), 1e-6) << c.p.transpose();
    }
}

TEST(MeshTopology, ThePseudoNormalsSignTellsInsideFromOutside) {
    const TriangleMesh box = to_triangle_mesh(test_meshes::box(kCenter, kHalf, false));
    const MeshTopology topology(box, kMeshTopologyMemory);
    std::mt19937_64 random(23);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int inside = 0, outside = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        // Points near the surface, corners and edges included, and far away.
        const double spread = trial % 2 == 0 ? 0.05 : 0.3;
        const Vec3 p(spread * u(random), spread * u(random), spread * u(random));
        const bool really_inside =
            std::fabs(p.x()) < kHalf[0] && std::fabs(p.y()) < kHalf[1] && std::fabs(p.z()) < kHalf[2];
        const auto closest = brute_force_closest(box, p);
        if (closest.distance < 1e-9) continue;
        const double side = (p - closest.point.point).dot(topology.pseudo_normal(closest.triangle, closest.point.feature));
        ASSERT_EQ(side < 0.0, really_inside) << p.transpose();
        (really_inside ? inside : outside) += 1;
    }
    EXPECT_GT(inside, 100);
    EXPECT_GT(outside, 1000);
}

}  // namespace
}  // namespace enteron::collision
