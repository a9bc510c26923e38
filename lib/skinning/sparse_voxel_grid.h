// SPDX-License-Identifier: Apache-2.0
// The narrow band of voxels around the axis, stored sparsely: blocks of 8^3 lattice corners
// found through a hash of their block coordinates, allocated only where the skeleton
// touches. A 6 m bowel in a 0.4 m abdomen touches a few hundred blocks; a dense grid of
// the abdomen at the same resolution would hold millions of corners per frame.
// The lattice is anchored at the world origin (corner (i, j, k) sits at voxel * (i, j, k)),
// so it does not swim with the bowel from one frame to the next.
//
// A block stores its corners as separate arrays (structure of arrays), so the passes that
// read one quantity of every corner (the field for marching cubes, the nearest skeleton
// point for the field) stream through contiguous memory; a row of 8 corners' nearest
// points is one 64-byte cache line.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "skinning/index_hash.h"

namespace enteron::skinning {

constexpr int kBlockSize = 8;                                        // corners per block side
constexpr int kBlockCorners = kBlockSize * kBlockSize * kBlockSize;  // 512

// A corner's nearest skeleton point and the squared distance to it, as one 64-bit key:
// the distance's float bits (monotonic for non-negative floats) above the point's index, so
// that the smaller key is the nearer point and a splat keeps the nearest with one min.
constexpr uint64_t kOutsideBand = ~uint64_t{0};  // no skeleton point near: outside the band
inline uint64_t nearest_key(float distance2_m2, uint32_t point) {
    uint32_t bits;
    std::memcpy(&bits, &distance2_m2, sizeof bits);
    return (uint64_t(bits) << 32) | point;
}
// The point of a key; -1 outside the band.
inline int32_t nearest_point(uint64_t key) { return key == kOutsideBand ? -1 : int32_t(uint32_t(key)); }

struct VoxelBlock {
    std::array<int32_t, 3> coordinates{};  // block coordinates: corner index / kBlockSize
    // Per corner (local_index): the field there (negative outside the band: counts as
    // outside the surface) and the nearest skeleton point (nearest_key).
    std::array<float, kBlockCorners> field;
    std::array<uint64_t, kBlockCorners> nearest;
};

class SparseVoxelGrid {
public:
    // Forgets every block (their memory is kept for the next frame).
    void reset(double voxel_size, std::size_t expected_blocks);

    double voxel_size() const { return voxel_; }
    std::size_t block_count() const { return used_; }
    VoxelBlock& block(std::size_t i) { return blocks_[i]; }
    const VoxelBlock& block(std::size_t i) const { return blocks_[i]; }

    // The index of the block at block coordinates (bx, by, bz), made (every corner outside
    // the band) if absent. Indices stay valid until reset; references may not (the block
    // storage grows, with headroom: frame_buffers.h).
    uint32_t touch(int32_t bx, int32_t by, int32_t bz);
    // The block's index, or kMissing if the band does not reach it.
    uint32_t find(int32_t bx, int32_t by, int32_t bz) const { return lookup_.find(pack(bx, by, bz)); }
    static constexpr uint32_t kMissing = IndexHash::kMissing;

    static std::size_t local_index(int x, int y, int z) {
        return std::size_t(x) + kBlockSize * (std::size_t(y) + kBlockSize * std::size_t(z));
    }
    static uint64_t pack(int32_t x, int32_t y, int32_t z) {
        const auto m = [](int32_t v) { return uint64_t(uint32_t(v + (1 << 20))) & 0x1fffffULL; };
        return (m(x) << 42) | (m(y) << 21) | m(z);
    }
    // Block coordinate of lattice index i (floor division by kBlockSize).
    static int32_t block_of(int32_t i) { return i >= 0 ? i / kBlockSize : -((-i + kBlockSize - 1) / kBlockSize); }

private:
    double voxel_ = 0.0;
    std::vector<VoxelBlock> blocks_;
    std::size_t used_ = 0;
    IndexHash lookup_;
};

}  // namespace enteron::skinning
