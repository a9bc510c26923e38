// SPDX-License-Identifier: Apache-2.0
#include "skinning/sparse_voxel_grid.h"

#include "skinning/frame_buffers.h"

namespace enteron::skinning {

void SparseVoxelGrid::reset(double voxel_size, std::size_t expected_blocks) {
    voxel_ = voxel_size;
    used_ = 0;
    lookup_.clear(expected_blocks);
}

uint32_t SparseVoxelGrid::touch(int32_t bx, int32_t by, int32_t bz) {
    bool inserted = false;
    const uint32_t index = lookup_.find_or_insert(pack(bx, by, bz), uint32_t(used_), &inserted);
    if (!inserted) return index;
    if (used_ == blocks_.size()) {
        reserve_with_headroom(blocks_, used_ + 1);
        blocks_.emplace_back();
    }
    VoxelBlock& b = blocks_[used_++];
    b.coordinates = {bx, by, bz};
    b.nearest.fill(kOutsideBand);
    return index;
}

}  // namespace enteron::skinning
