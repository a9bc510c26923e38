// SPDX-License-Identifier: Apache-2.0
// A uniform grid stored as a hash table: the candidate pairs of points closer than a cell
// size, in O(N). Each bucket is a list threaded through the points (one index per point),
// so a point that moved is refiled on its own (move) and the grid follows a pile from step
// to step without being rebuilt; build files every point at once. Arrays are sized once for
// the point count: it never allocates after construction.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "base/state_io.h"

namespace enteron::collision {

class SpatialHash {
public:
    // `cell` (m) must be at least the largest distance at which a pair matters.
    SpatialHash(std::size_t capacity, double cell, std::pmr::memory_resource* memory);

    // Files `count` points (x y z each, `stride` doubles apart), forgetting any before.
    void build(const double* points, std::size_t count, std::size_t stride);

    // Refiles point i (already filed) at position p.
    void move(std::size_t i, const Vec3& p);

    // Save and restore (base/state_io.h): the points filed, bucket by bucket in list order.
    // A bucket's order is the history of its moves, and the order of the neighbours a
    // search visits follows it; a grid restored from it visits them in the same order.
    void save_filing(StateWriter& out) const;
    // Reads what save_filing wrote and, unless checking, refiles the points (x y z each,
    // `stride` doubles apart, where they were filed) in that order. The points listed must
    // be each filed point once. `scratch` lends the work space of the check.
    void restore_filing(StateReader& in, const double* points, std::size_t stride,
                        std::pmr::memory_resource* scratch);

    // Calls visit(i, j) once for every unordered pair of points in the same or
    // neighbouring cells (a superset of the pairs closer than a cell); i and j in any order.
    template <class Visit>
    void for_each_candidate_pair(Visit&& visit) const;

    // Calls visit(j) for every point j in the cell of point i or a neighbouring one (a
    // superset of the points closer than a cell to point i), i itself included.
    template <class Visit>
    void for_each_neighbour(std::size_t i, Visit&& visit) const;

private:
    static constexpr int32_t kEnd = -1;  // the end of a bucket's list

    std::array<int64_t, 3> cell_of(const double* p) const;
    std::size_t bucket_of(int64_t x, int64_t y, int64_t z) const {
        // The classic spatial hash of Teschner et al. 2003.
        const uint64_t h = (static_cast<uint64_t>(x) * 73856093u) ^ (static_cast<uint64_t>(y) * 19349663u) ^
                           (static_cast<uint64_t>(z) * 83492791u);
        return static_cast<std::size_t>(h & mask_);
    }
    // One integer per cell (21 bits per coordinate: unique within a million cells each way).
    static uint64_t key_of(int64_t x, int64_t y, int64_t z) {
        constexpr uint64_t kMask = (uint64_t{1} << 21) - 1;
        return ((static_cast<uint64_t>(x) & kMask) << 42) | ((static_cast<uint64_t>(y) & kMask) << 21) |
               (static_cast<uint64_t>(z) & kMask);
    }
    // Files point i (cell, key and bucket set) at the head of its bucket's list.
    void link(std::size_t i);
    // Calls visit(j) for each point j in cell (x, y, z). A bucket may hold several cells
    // (hash collisions): a point counts only if it really sits in that cell.
    template <class Visit>
    void for_each_in_cell(int64_t x, int64_t y, int64_t z, Visit&& visit) const {
        const uint64_t key = key_of(x, y, z);
        for (int32_t j = head_[bucket_of(x, y, z)]; j != kEnd; j = next_[static_cast<std::size_t>(j)])
            if (point_key_[static_cast<std::size_t>(j)] == key) visit(static_cast<std::size_t>(j));
    }

    double inverse_cell_;
    std::size_t mask_;                     // buckets - 1 (a power of two)
    std::pmr::vector<int32_t> head_;       // per bucket: its first point, or kEnd
    std::pmr::vector<int32_t> next_;       // per point: the next point of its bucket, or kEnd
    std::pmr::vector<std::array<int64_t, 3>> point_cell_;
    std::pmr::vector<uint64_t> point_key_;
    std::pmr::vector<uint32_t> point_bucket_;
    std::size_t count_ = 0;
};

template <class Visit>
void SpatialHash::for_each_candidate_pair(Visit&& visit) const {
    // Each unordered pair once: a point's own cell (partners with a larger index) and the
    // 13 neighbouring cells of the forward half-stencil (offsets after (0, 0, 0) in
    // lexicographic order).
    static constexpr int kForward[13][3] = {{0, 0, 1},  {0, 1, -1}, {0, 1, 0},  {0, 1, 1},  {1, -1, -1},
                                            {1, -1, 0}, {1, -1, 1}, {1, 0, -1}, {1, 0, 0},  {1, 0, 1},
                                            {1, 1, -1}, {1, 1, 0},  {1, 1, 1}};
    for (std::size_t i = 0; i < count_; ++i) {
        const auto& c = point_cell_[i];
        for_each_in_cell(c[0], c[1], c[2], [&](std::size_t j) {
            if (j > i) visit(i, j);
        });
        for (const auto& offset : kForward)
            for_each_in_cell(c[0] + offset[0], c[1] + offset[1], c[2] + offset[2],
                             [&](std::size_t j) { visit(i, j); });
    }
}

template <class Visit>
void SpatialHash::for_each_neighbour(std::size_t i, Visit&& visit) const {
    const auto& c = point_cell_[i];
    for (int64_t dx = -1; dx <= 1; ++dx)
        for (int64_t dy = -1; dy <= 1; ++dy)
            for (int64_t dz = -1; dz <= 1; ++dz) for_each_in_cell(c[0] + dx, c[1] + dy, c[2] + dz, visit);
}

}  // namespace enteron::collision
