#include "collision/spatial_hash.h"

#include <cmath>

namespace enteron::collision {

SpatialHash::SpatialHash(std::size_t capacity, double cell, std::pmr::memory_resource* memory)
    : inverse_cell_(1.0 / cell),
      mask_(0),
      bucket_start_(memory),
      order_(memory),
      point_bucket_(memory),
      point_cell_(memory),
      point_key_(memory) {
    std::size_t buckets = 64;
    while (buckets < 2 * capacity) buckets *= 2;
    mask_ = buckets - 1;
    bucket_start_.assign(buckets + 1, 0);
    order_.assign(capacity, 0);
    point_bucket_.assign(capacity, 0);
    point_cell_.assign(capacity, {0, 0, 0});
    point_key_.assign(capacity, 0);
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

std::size_t SpatialHash::bucket_of(int64_t x, int64_t y, int64_t z) const {
    // The classic spatial hash of Teschner et al. 2003.
    const uint64_t h = (static_cast<uint64_t>(x) * 73856093u) ^ (static_cast<uint64_t>(y) * 19349663u) ^
                       (static_cast<uint64_t>(z) * 83492791u);
    return static_cast<std::size_t>(h & mask_);
}

void SpatialHash::build(const double* points, std::size_t count, std::size_t stride) {
    count_ = count;
    std::fill(bucket_start_.begin(), bucket_start_.end(), 0u);
    for (std::size_t i = 0; i < count; ++i) {
        point_cell_[i] = cell_of(points + i * stride);
        const auto& c = point_cell_[i];
        point_key_[i] = key_of(c[0], c[1], c[2]);
        point_bucket_[i] = static_cast<uint32_t>(bucket_of(c[0], c[1], c[2]));
        bucket_start_[point_bucket_[i] + 1] += 1;
    }
    for (std::size_t b = 1; b < bucket_start_.size(); ++b) bucket_start_[b] += bucket_start_[b - 1];
    // Fill each bucket from its end so no cursor array is needed.
    for (std::size_t i = count; i-- > 0;) order_[--bucket_start_[point_bucket_[i] + 1]] = static_cast<uint32_t>(i);
    // bucket_start_[b + 1] now holds the start of bucket b; shift back.
    for (std::size_t b = 0; b + 1 < bucket_start_.size(); ++b) bucket_start_[b] = bucket_start_[b + 1];
    bucket_start_.back() = static_cast<uint32_t>(count);
}

}  // namespace enteron::collision
