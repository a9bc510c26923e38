// SPDX-License-Identifier: Apache-2.0
// A triangle mesh as the caller gave it (ent_obstacle_desc, a JSON "mesh" obstacle, an OBJ
// or PLY file): vertex coordinates in the obstacle's frame and three vertex indices per
// triangle, counter-clockwise seen from the side the bowel is kept on. Copied from the
// caller and checked (scene/validate.h) before anything is built from it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"

namespace enteron::collision {

struct TriangleMesh {
    TriangleMesh() = default;
    // A copy in `memory` (a scene's).
    TriangleMesh(const TriangleMesh& other, std::pmr::memory_resource* memory)
        : vertices(other.vertices, memory), indices(other.indices, memory) {}

    std::pmr::vector<double> vertices;   // x y z per vertex, m
    std::pmr::vector<uint32_t> indices;  // a b c per triangle

    std::size_t vertex_count() const { return vertices.size() / 3; }
    std::size_t triangle_count() const { return indices.size() / 3; }
    Vec3 vertex(std::size_t i) const { return point_at(vertices.data(), i); }
    Vec3 corner(std::size_t triangle, int k) const { return vertex(indices[3 * triangle + k]); }
};

// The most triangles a mesh obstacle may have: far beyond an organ segmented from CT
// (20k-200k) and small enough that a count claimed by mistake is refused before any
// memory is touched.
constexpr std::size_t kMaxMeshTriangles = std::size_t{1} << 24;  // 16.8 million

}  // namespace enteron::collision
