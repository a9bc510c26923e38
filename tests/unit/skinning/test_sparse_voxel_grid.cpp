// SPDX-License-Identifier: Apache-2.0
// The sparse band of voxel blocks (lib/skinning/sparse_voxel_grid.h): a block is made once,
// with no skeleton point near any corner, and found again by its coordinates (negative ones
// too); reset forgets the blocks; block coordinates are floor divisions; corners are laid
// out x fastest; a nearer skeleton point has the smaller key.
#include <gtest/gtest.h>

#include <set>

#include "skinning/sparse_voxel_grid.h"

namespace enteron::skinning {
namespace {

TEST(SparseVoxelGrid, ABlockIsMadeOnceAndFoundByItsCoordinates) {
    SparseVoxelGrid grid;
    grid.reset(0.004, 4);
    EXPECT_EQ(grid.voxel_size(), 0.004);
    const uint32_t a = grid.touch(0, 0, 0), b = grid.touch(-1, 2, -300);
    EXPECT_NE(a, b);
    EXPECT_EQ(grid.touch(-1, 2, -300), b) << "touched again: the same block";
    EXPECT_EQ(grid.block_count(), 2u);
    EXPECT_EQ(grid.find(-1, 2, -300), b);
    EXPECT_EQ(grid.find(1, 2, -300), SparseVoxelGrid::kMissing);
    EXPECT_EQ(grid.block(b).coordinates, (std::array<int32_t, 3>{-1, 2, -300}));
    for (std::size_t c = 0; c < kBlockCorners; ++c) ASSERT_EQ(grid.block(b).nearest[c], kOutsideBand);
    // Many blocks: the storage grows, the indices stay.
    for (int32_t i = 0; i < 200; ++i) grid.touch(i, -i, 7);
    EXPECT_EQ(grid.find(-1, 2, -300), b);
    EXPECT_EQ(grid.block_count(), 202u);
    grid.reset(0.004, 4);
    EXPECT_EQ(grid.block_count(), 0u);
    EXPECT_EQ(grid.find(0, 0, 0), SparseVoxelGrid::kMissing);
}

TEST(SparseVoxelGrid, CoordinatesAndKeys) {
    EXPECT_EQ(SparseVoxelGrid::block_of(0), 0);
    EXPECT_EQ(SparseVoxelGrid::block_of(7), 0);
    EXPECT_EQ(SparseVoxelGrid::block_of(8), 1);
    EXPECT_EQ(SparseVoxelGrid::block_of(-1), -1) << "floor, not truncation";
    EXPECT_EQ(SparseVoxelGrid::block_of(-8), -1);
    EXPECT_EQ(SparseVoxelGrid::block_of(-9), -2);
    EXPECT_EQ(SparseVoxelGrid::local_index(1, 0, 0), 1u);
    EXPECT_EQ(SparseVoxelGrid::local_index(0, 1, 0), 8u);
    EXPECT_EQ(SparseVoxelGrid::local_index(7, 7, 7), std::size_t(kBlockCorners - 1));
    std::set<uint64_t> packed;
    for (int32_t x : {-2, -1, 0, 1})
        for (int32_t y : {-1, 0, 1})
            for (int32_t z : {-1, 0, 1}) packed.insert(SparseVoxelGrid::pack(x, y, z));
    EXPECT_EQ(packed.size(), 36u) << "distinct coordinates, distinct keys";
    EXPECT_LT(nearest_key(0.5f, 9), nearest_key(0.75f, 2)) << "the nearer point wins a min";
    EXPECT_LT(nearest_key(0.5f, 2), nearest_key(0.5f, 9));
    EXPECT_EQ(nearest_point(nearest_key(1e-6f, 1234)), 1234);
    EXPECT_EQ(nearest_point(kOutsideBand), -1);
}

}  // namespace
}  // namespace enteron::skinning
