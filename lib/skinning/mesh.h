// SPDX-License-Identifier: Apache-2.0
// The triangle mesh a skin produces: flat float arrays a renderer can upload as they are.
// Buffers only grow (resize keeps capacity), so a skin updated every frame stops
// allocating once it has seen its largest mesh.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/geometry.h"

namespace enteron::skinning {

struct Mesh {
    std::vector<float> positions;  // x y z per vertex, m
    std::vector<float> normals;    // unit outward normal per vertex
    std::vector<float> tangents;   // unit, perpendicular to the normal, along increasing u (x y z per vertex)
    std::vector<float> u;          // axis parameter per vertex: arc length / total length, [0, 1]
    std::vector<float> v;          // around the axis per vertex: angle in the rotation-minimising frame / 2 pi, [0, 1)
    std::vector<uint32_t> indices; // 3 per triangle, counter-clockwise seen from outside

    std::size_t vertex_count() const { return u.size(); }
    std::size_t triangle_count() const { return indices.size() / 3; }

    void resize_vertices(std::size_t count) {
        positions.resize(3 * count);
        normals.resize(3 * count);
        tangents.resize(3 * count);
        u.resize(count);
        v.resize(count);
    }
    void clear() {
        positions.clear();
        normals.clear();
        tangents.clear();
        u.clear();
        v.clear();
        indices.clear();
    }
};

// Writes v as the index-th float triple of a positions or normals buffer.
inline void store_vec3(std::vector<float>& buffer, std::size_t index, Vec3 v) {
    buffer[3 * index] = float(v.x());
    buffer[3 * index + 1] = float(v.y());
    buffer[3 * index + 2] = float(v.z());
}

}  // namespace enteron::skinning
