// A uniform grid stored as a hash table: the candidate pairs of spheres closer than a cell
// size, in O(N). Rebuilt from scratch for every evaluation by a counting sort into the
// buckets, into arrays sized once for the sphere count, so it never allocates after the
// first build.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

namespace enteron::collision {

class SpatialHash {
public:
    // `cell` (m) must be at least the largest distance at which a pair matters.
    SpatialHash(std::size_t capacity, double cell, std::pmr::memory_resource* memory);

    // Sorts `count` points (x y z each, `stride` doubles apart) into the buckets.
    void build(const double* points, std::size_t count, std::size_t stride);

    // Calls visit(i, j) once for every unordered pair of points in the same or
    // neighbouring cells (a superset of the pairs closer than a cell); i and j in any order.
    template <class Visit>
    void for_each_candidate_pair(Visit&& visit) const;

    // Calls visit(j) for every point j in the cell of point i or a neighbouring one (a
    // superset of the points closer than a cell to point i), i itself included.
    template <class Visit>
    void for_each_neighbour(std::size_t i, Visit&& visit) const;

private:
    std::array<int64_t, 3> cell_of(const double* p) const;
    std::size_t bucket_of(int64_t x, int64_t y, int64_t z) const;
    // One integer per cell (21 bits per coordinate: unique within a million cells each way).
    static uint64_t key_of(int64_t x, int64_t y, int64_t z) {
        constexpr uint64_t kMask = (uint64_t{1} << 21) - 1;
        return ((static_cast<uint64_t>(x) & kMask) << 42) | ((static_cast<uint64_t>(y) & kMask) << 21) |
               (static_cast<uint64_t>(z) & kMask);
    }

    double inverse_cell_;
    std::size_t mask_;                        // buckets - 1 (a power of two)
    std::pmr::vector<uint32_t> bucket_start_; // buckets + 1 offsets into order_
    std::pmr::vector<uint32_t> order_;        // point indices sorted by bucket
    std::pmr::vector<uint32_t> point_bucket_;
    std::pmr::vector<std::array<int64_t, 3>> point_cell_;
    std::pmr::vector<uint64_t> point_key_;
    std::size_t count_ = 0;
};

template <class Visit>
void SpatialHash::for_each_candidate_pair(Visit&& visit) const {
    // Each unordered pair once: a point's own cell (partners with a larger index) and the
    // 13 neighbouring cells of the forward half-stencil (offsets after (0, 0, 0) in
    // lexicographic order). A bucket may hold several cells (hash collisions): a partner
    // counts only if it really sits in the cell being visited.
    static constexpr int kForward[13][3] = {{0, 0, 1},  {0, 1, -1}, {0, 1, 0},  {0, 1, 1},  {1, -1, -1},
                                            {1, -1, 0}, {1, -1, 1}, {1, 0, -1}, {1, 0, 0},  {1, 0, 1},
                                            {1, 1, -1}, {1, 1, 0},  {1, 1, 1}};
    for (std::size_t i = 0; i < count_; ++i) {
        const auto& c = point_cell_[i];
        const std::size_t own = point_bucket_[i];
        const uint64_t own_key = point_key_[i];
        for (uint32_t slot = bucket_start_[own]; slot < bucket_start_[own + 1]; ++slot) {
            const uint32_t j = order_[slot];
            if (j > i && point_key_[j] == own_key) visit(i, static_cast<std::size_t>(j));
        }
        for (const auto& offset : kForward) {
            const int64_t x = c[0] + offset[0], y = c[1] + offset[1], z = c[2] + offset[2];
            const std::size_t b = bucket_of(x, y, z);
            const uint64_t key = key_of(x, y, z);
            for (uint32_t slot = bucket_start_[b]; slot < bucket_start_[b + 1]; ++slot) {
                const uint32_t j = order_[slot];
                if (point_key_[j] == key) visit(i, static_cast<std::size_t>(j));
            }
        }
    }
}

template <class Visit>
void SpatialHash::for_each_neighbour(std::size_t i, Visit&& visit) const {
    const auto& c = point_cell_[i];
    for (int64_t dx = -1; dx <= 1; ++dx)
        for (int64_t dy = -1; dy <= 1; ++dy)
            for (int64_t dz = -1; dz <= 1; ++dz) {
                const int64_t x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
                const std::size_t b = bucket_of(x, y, z);
                const uint64_t key = key_of(x, y, z);
                for (uint32_t slot = bucket_start_[b]; slot < bucket_start_[b + 1]; ++slot) {
                    const uint32_t j = order_[slot];
                    if (point_key_[j] == key) visit(static_cast<std::size_t>(j));
                }
            }
}

}  // namespace enteron::collision
