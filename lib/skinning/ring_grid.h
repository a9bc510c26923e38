// SPDX-License-Identifier: Apache-2.0
// The topology shared by the tube and the convolution skins: a closed tube made of rows of
// vertices around the axis. Row 0 is the pole of the first end cap, then `cap_rings`
// rings of that cap, the `body_rings` rings along the axis, the rings of the last cap and
// its pole. Every vertex has a fixed place (row, angle), so the mesh is closed
// (watertight) by construction and a skin can solve each vertex along its own ray.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/geometry.h"

namespace enteron::skinning {

class RingGrid {
public:
    // Rebuilds the triangle indices (and, for a new segment count, the ring's angles) when
    // the shape of the grid changed; returns true then.
    bool layout(std::size_t body_rings, std::size_t segments, std::size_t cap_rings, std::vector<uint32_t>& indices);

    std::size_t rows() const { return body_rings_ + 2 * cap_rings_ + 2; }
    std::size_t segments() const { return segments_; }
    std::size_t cap_rings() const { return cap_rings_; }
    std::size_t body_rings() const { return body_rings_; }
    std::size_t vertex_count() const { return 2 + (rows() - 2) * segments_; }
    // Row of body ring k.
    std::size_t body_row(std::size_t k) const { return cap_rings_ + 1 + k; }
    // Index of vertex j of row r (any j for a pole row).
    std::size_t vertex(std::size_t row, std::size_t j) const {
        if (row == 0) return 0;
        if (row + 1 == rows()) return vertex_count() - 1;
        return 1 + (row - 1) * segments_ + (j % segments_);
    }
    // Polar angle, from the equator of the cap towards its pole, of row r of a cap (rad);
    // 0 for body rows. Sign: negative on the first cap (towards -t), positive on the last.
    double cap_angle(std::size_t row) const;
    // cos and sin of the angle of vertex j around a ring, 2 pi j / segments.
    double cosine(std::size_t j) const { return cosine_[j]; }
    double sine(std::size_t j) const { return sine_[j]; }
    const double* cosines() const { return cosine_.data(); }
    const double* sines() const { return sine_.data(); }

    // v of every vertex (angle around the ring / 2 pi: j / segments; 0 at the poles).
    void around(float* v) const;

    // Outward vertex normals and unit tangents from central differences on the grid: the
    // normal across the positions of a ring and of its neighbouring rows, the tangent along
    // the rows (towards the last pole, made perpendicular to the normal). The poles take the
    // end tangents as normals, and the direction of their meridian j = 0 as tangent.
    void grid_normals(const float* positions, Vec3 first_tangent, Vec3 last_tangent, float* normals,
                      float* tangents) const;

private:
    std::size_t body_rings_ = 0, segments_ = 0, cap_rings_ = 0;
    std::vector<double> cosine_, sine_;
};

}  // namespace enteron::skinning
