// SPDX-License-Identifier: Apache-2.0
#include "skinning/ring_grid.h"

#include <cmath>

namespace enteron::skinning {

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kTwoPi = 6.28318530717958647692;
}

bool RingGrid::layout(std::size_t body_rings, std::size_t segments, std::size_t cap_rings,
                      std::vector<uint32_t>& indices) {
    if (body_rings == body_rings_ && segments == segments_ && cap_rings == cap_rings_ && !indices.empty())
        return false;
    body_rings_ = body_rings;
    if (segments != segments_) {
        cosine_.resize(segments);
        sine_.resize(segments);
        for (std::size_t j = 0; j < segments; ++j) {
            cosine_[j] = std::cos(kTwoPi * double(j) / double(segments));
            sine_[j] = std::sin(kTwoPi * double(j) / double(segments));
        }
    }
    segments_ = segments;
    cap_rings_ = cap_rings;
    indices.clear();
    // Quad between rows r and r+1: a=(r,j) b=(r,j+1) c=(r+1,j+1) d=(r+1,j). With rows along
    // +t and j turning from the normal towards the binormal, (a, b, c) faces outwards.
    const std::size_t n = rows();
    for (std::size_t r = 0; r + 1 < n; ++r) {
        for (std::size_t j = 0; j < segments_; ++j) {
            const auto a = uint32_t(vertex(r, j)), b = uint32_t(vertex(r, j + 1));
            const auto c = uint32_t(vertex(r + 1, j + 1)), d = uint32_t(vertex(r + 1, j));
            if (r == 0) {  // fan around the first pole
                indices.insert(indices.end(), {a, c, d});
            } else if (r + 2 == n) {  // fan around the last pole
                indices.insert(indices.end(), {a, b, c});
            } else {
                indices.insert(indices.end(), {a, b, c, a, c, d});
            }
        }
    }
    return true;
}

double RingGrid::cap_angle(std::size_t row) const {
    const double step = kHalfPi / double(cap_rings_ + 1);
    if (row <= cap_rings_) return -double(cap_rings_ + 1 - row) * step;
    const std::size_t last_body = cap_rings_ + body_rings_;
    if (row > last_body) return double(row - last_body) * step;
    return 0.0;
}

void RingGrid::around(float* v) const {
    v[0] = 0.0f;
    v[vertex_count() - 1] = 0.0f;
    for (std::size_t r = 1; r + 1 < rows(); ++r)
        for (std::size_t j = 0; j < segments_; ++j) v[vertex(r, j)] = float(double(j) / double(segments_));
}

void RingGrid::grid_normals(const float* positions, Vec3 first_tangent, Vec3 last_tangent, float* normals,
                            float* tangents) const {
    auto at = [&](std::size_t index) {
        return Vec3{positions[3 * index], positions[3 * index + 1], positions[3 * index + 2]};
    };
    auto store = [](float* buffer, std::size_t index, Vec3 v) {
        buffer[3 * index] = float(v.x());
        buffer[3 * index + 1] = float(v.y());
        buffer[3 * index + 2] = float(v.z());
    };
    // The part of `along` perpendicular to the unit normal n, unit.
    auto tangent = [](Vec3 along, Vec3 n) { return normalized_or(along - along.dot(n) * n, Vec3{0, 0, 1}); };
    const std::size_t n = rows(), last = vertex_count() - 1;
    const Vec3 first_normal = -1.0 * first_tangent;
    store(normals, 0, first_normal);
    store(tangents, 0, tangent(at(vertex(1, 0)) - at(0), first_normal));
    store(normals, last, last_tangent);
    store(tangents, last, tangent(at(last) - at(vertex(n - 2, 0)), last_tangent));
    for (std::size_t r = 1; r + 1 < n; ++r) {
        for (std::size_t j = 0; j < segments_; ++j) {
            const Vec3 around = at(vertex(r, j + 1)) - at(vertex(r, j + segments_ - 1));
            const Vec3 along = at(vertex(r + 1, j)) - at(vertex(r - 1, j));
            Vec3 normal = around.cross(along);
            const double length = normal.norm();
            if (length > 1e-300) {
                normal = (1.0 / length) * normal;
            } else {  // a degenerate ring: away from the opposite vertex
                const Vec3 away = at(vertex(r, j)) - 0.5 * (at(vertex(r, j + segments_ / 2)) + at(vertex(r, j)));
                normal = normalized_or(away, Vec3{0, 0, 1});
            }
            store(normals, vertex(r, j), normal);
            store(tangents, vertex(r, j), tangent(along, normal));
        }
    }
}

}  // namespace enteron::skinning
