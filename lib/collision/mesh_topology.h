// SPDX-License-Identifier: Apache-2.0
// What a triangle mesh's connectivity says about it, and the pseudo-normals that sign its
// distance field. Baerentzen and Aanaes, "Signed distance computation using the angle
// weighted pseudonormal" (IEEE TVCG 2005): the closest point of a closed, consistently
// oriented mesh lies on a face, an edge or a vertex, and the sign of (p - closest) . n, with
// n the face normal, the sum of the two faces' normals at an edge, or the angle-weighted
// sum of the normals around a vertex, tells inside from outside exactly.
//
// An open or non-manifold mesh has no inside; the same rule then gives one-sided contact:
// the bowel is pushed to the side the triangles' normals (counter-clockwise winding) face.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "collision/closest_point_on_triangle.h"
#include "collision/triangle_mesh.h"

namespace enteron::collision {

struct MeshTopologyReport {
    std::size_t open_edges = 0;         // edges of one triangle
    std::size_t nonmanifold_edges = 0;  // edges of three or more triangles
    std::size_t flipped_edges = 0;      // edges two triangles run along in the same direction
    std::size_t degenerate_triangles = 0;  // zero area (ignored)
    double signed_volume = 0.0;         // m^3, < 0 when the normals face inward (a cavity)
    bool closed() const { return open_edges == 0 && nonmanifold_edges == 0 && flipped_edges == 0; }
};

class MeshTopology {
public:
    // Builds the normals of a checked mesh (indices in range, vertices finite).
    MeshTopology(const TriangleMesh& mesh, std::pmr::memory_resource* memory);

    const MeshTopologyReport& report() const { return report_; }
    // Whether triangle t has an area (the others never take part in contacts).
    bool usable(std::size_t triangle) const { return usable_[triangle] != 0; }
    // The pseudo-normal (not unit) of a feature of triangle t.
    Vec3 pseudo_normal(std::size_t triangle, TriangleFeature feature) const;

private:
    const TriangleMesh& mesh_;
    std::pmr::vector<float> face_normals_;    // unit, 3 per triangle
    std::pmr::vector<float> edge_normals_;    // 9 per triangle: edges ab, bc, ca
    std::pmr::vector<float> vertex_normals_;  // 3 per vertex
    std::pmr::vector<uint8_t> usable_;
    MeshTopologyReport report_;
};

}  // namespace enteron::collision
