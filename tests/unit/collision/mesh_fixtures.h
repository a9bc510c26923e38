// SPDX-License-Identifier: Apache-2.0
// Shared by the tests of the mesh obstacles' units (closest_point_on_triangle, mesh_topology,
// triangle_bvh, mesh_distance_field): the test meshes of tests/support/test_meshes.h as the
// library's TriangleMesh, and the brute-force closest point the accelerated ones must match.
#pragma once

#include <limits>

#include "collision/closest_point_on_triangle.h"
#include "collision/triangle_mesh.h"
#include "test_meshes.h"

namespace collision_test {

inline enteron::collision::TriangleMesh to_triangle_mesh(const test_meshes::Mesh& m) {
    enteron::collision::TriangleMesh mesh;
    mesh.vertices.assign(m.vertices.begin(), m.vertices.end());
    mesh.indices.assign(m.triangles.begin(), m.triangles.end());
    return mesh;
}

// Every triangle tried: the closest point, its triangle and distance.
struct BruteForceClosest {
    std::size_t triangle = 0;
    enteron::collision::TrianglePoint point{enteron::Vec3::Zero(), enteron::collision::TriangleFeature::face};
    double distance = std::numeric_limits<double>::infinity();
};
inline BruteForceClosest brute_force_closest(const enteron::collision::TriangleMesh& mesh, const enteron::Vec3& p) {
    BruteForceClosest best;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const auto point = enteron::collision::closest_point_on_triangle(p, mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2));
        const double distance = (p - point.point).norm();
        if (distance < best.distance) best = {t, point, distance};
    }
    return best;
}

}  // namespace collision_test
