// SPDX-License-Identifier: Apache-2.0
#include "collision/spatial_hash.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace enteron::collision {

SpatialHash::SpatialHash(std::size_t capacity, double cell, std::pmr::memory_resource* memory)
    : inverse_cell_(1.0 / cell),
      mask_(0),
      head_(memory),
      next_(capacity, kEnd, memory),
      point_cell_(capacity, {0, 0, 0}, memory),
      point_key_(capacity, 0, memory),
      point_bucket_(capacity, 0, memory) {
    std::size_t buckets = 64;
    while (buckets < 2 * capacity) buckets *= 2;
    mask_ = buckets - 1;
    head_.assign(buckets, kEnd);
}

std::array<int64_t, 3> SpatialHash::cell_of(const double* p) const {
    // Far-away or non-finite coordinates land in some cell; the distance test sorts them out.
    auto index = [&](double x) {
        const double scaled = x * inverse_cell_;
        if (!(std::fabs(scaled) < 1e15)) return int64_t{0};  // also NaN
        // floor without a library call (baseline x86-64 has no rounding instruction)
        const auto truncated = static_cast<int64_t>(scaled);
        return static_cast<double>(truncated) > scaled ? truncated - 1 : truncated;
    };
    return {index(p[0]), index(p[1]), index(p[2])};
}

void SpatialHash::link(std::size_t i) {
    const auto& c = point_cell_[i];
    point_key_[i] = key_of(c[0], c[1], c[2]);
    point_bucket_[i] = static_cast<uint32_t>(bucket_of(c[0], c[1], c[2]));
    next_[i] = head_[point_bucket_[i]];
    head_[point_bucket_[i]] = static_cast<int32_t>(i);
}

void SpatialHash::build(const double* points, std::size_t count, std::size_t stride) {
    count_ = count;
    std::fill(head_.begin(), head_.end(), kEnd);
    // The last point first: each list then runs in increasing index.
    for (std::size_t i = count; i-- > 0;) {
        point_cell_[i] = cell_of(points + i * stride);
        link(i);
    }
}

void SpatialHash::move(std::size_t i, const Vec3& p) {
    const std::array<int64_t, 3> cell = cell_of(p.data());
    if (cell == point_cell_[i]) return;
    // Unlink from the old bucket (its list is a few points long); a point that was never
    // filed is only linked.
    int32_t* link_to_i = &head_[point_bucket_[i]];
    while (*link_to_i != kEnd && *link_to_i != static_cast<int32_t>(i))
        link_to_i = &next_[static_cast<std::size_t>(*link_to_i)];
    if (*link_to_i != kEnd) *link_to_i = next_[i];
    point_cell_[i] = cell;
    link(i);
}

void SpatialHash::save_filing(StateWriter& out) const {
    out.u32(static_cast<uint32_t>(count_));
    for (const int32_t head : head_)
        for (int32_t j = head; j != kEnd; j = next_[static_cast<std::size_t>(j)]) out.u32(static_cast<uint32_t>(j));
}

void SpatialHash::restore_filing(StateReader& in, const double* points, std::size_t stride,
                                 std::pmr::memory_resource* scratch) {
    const uint32_t count = in.count("points filed in the grid", next_.size());
    const unsigned char* order = in.raw("grid filing order", count * sizeof(uint32_t));
    auto at = [order](std::size_t k) {
        uint32_t i;
        std::memcpy(&i, order + k * sizeof i, sizeof i);
        return i;
    };
    if (in.checking()) {
        std::pmr::vector<uint8_t> seen(count, 0, scratch);  // allocates while checking only
        for (std::size_t k = 0; k < count; ++k) {
            const uint32_t i = at(k);
            if (i >= count || seen[i] != 0)
                in.fail("the grid's filing order is not each of its " + std::to_string(count) + " points once");
            seen[i] = 1;
        }
        return;
    }
    count_ = count;
    std::fill(head_.begin(), head_.end(), kEnd);
    // Linked last to first: each bucket's list comes back in the order it was saved.
    for (std::size_t k = count; k-- > 0;) {
        const std::size_t i = at(k);
        point_cell_[i] = cell_of(points + i * stride);
        link(i);
    }
}

}  // namespace enteron::collision
