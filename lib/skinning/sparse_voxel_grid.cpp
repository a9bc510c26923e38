#include "skinning/sparse_voxel_grid.h"

namespace enteron::skinning {

void SparseVoxelGrid::reset(double voxel_size, std::size_t expected_blocks) {
    voxel_ = voxel_size;
    used_ = 0;
    lookup_.clear(expected_blocks);
}

VoxelBlock& SparseVoxelGrid::touch(int32_t bx, int32_t by, int32_t bz) {
    bool inserted = false;
    const uint32_t index = lookup_.find_or_insert(pack(bx, by, bz), uint32_t(used_), &inserted);
    if (!inserted) return blocks_[index];
    if (used_ == blocks_.size()) blocks_.emplace_back();
    VoxelBlock& b = blocks_[used_++];
    b.coordinates = {bx, by, bz};
    b.corners.fill(VoxelCorner{0.0f, 0.0f, -1});
    return b;
}

const VoxelBlock* SparseVoxelGrid::find(int32_t bx, int32_t by, int32_t bz) const {
    const uint32_t index = lookup_.find(pack(bx, by, bz));
    return index == IndexHash::kMissing ? nullptr : &blocks_[index];
}

}  // namespace enteron::skinning
