// SPDX-License-Identifier: Apache-2.0
// Marching cubes on sparse voxel blocks (lib/skinning/marching_cubes.h): random fields give
// closed, consistently wound surfaces, across blocks too.
#include "skinning/marching_cubes.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "skinning/mesh.h"
#include "skinning/sparse_voxel_grid.h"

namespace {

using namespace enteron::skinning;

// Random field values in [-1, 1] at the corners of `block`, every corner in the band, and
// -1 (outside) on the outer layer of the lattice of `extent` corners per side that the
// block belongs to, so that the surface closes.
void fill_random(VoxelBlock& block, std::mt19937& random, int extent) {
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    for (int z = 0; z < kBlockSize; ++z)
        for (int y = 0; y < kBlockSize; ++y)
            for (int x = 0; x < kBlockSize; ++x) {
                const int g[3] = {block.coordinates[0] * kBlockSize + x, block.coordinates[1] * kBlockSize + y,
                                  block.coordinates[2] * kBlockSize + z};
                bool border = false;
                for (int c : g) border = border || c == 0 || c == extent - 1;
                const std::size_t i = SparseVoxelGrid::local_index(x, y, z);
                block.nearest[i] = nearest_key(0.0f, 0);
                block.field[i] = border ? -1.0f : value(random);
            }
}

// Every directed edge appears once and its reverse once: closed, manifold and
// consistently wound.
void expect_closed_and_consistently_wound(const Mesh& mesh) {
    std::vector<std::pair<uint32_t, uint32_t>> directed;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
        for (int e = 0; e < 3; ++e) directed.emplace_back(mesh.indices[3 * t + e], mesh.indices[3 * t + (e + 1) % 3]);
    std::sort(directed.begin(), directed.end());
    std::size_t failures = 0;
    for (std::size_t i = 0; i < directed.size() && failures < 10; ++i) {
        const auto [a, b] = directed[i];
        const bool once = (i == 0 || directed[i - 1] != directed[i]) &&
                          (i + 1 == directed.size() || directed[i + 1] != directed[i]);
        const bool reverse = std::binary_search(directed.begin(), directed.end(), std::make_pair(b, a));
        EXPECT_TRUE(once && reverse) << "edge " << a << " -> " << b;
        if (!(once && reverse)) ++failures;
    }
}

TEST(MarchingCubes, RandomFieldGivesAClosedConsistentlyWoundSurface) {
    // Random signs on a small lattice exercise every ambiguous face; the band covers the
    // lattice and its outer layer is outside, so the surface must close.
    std::mt19937 random(7);
    SparseVoxelGrid grid;
    grid.reset(1.0, 8);
    fill_random(grid.block(grid.touch(0, 0, 0)), random, kBlockSize);
    Mesh mesh;
    std::vector<int32_t> seeds;
    MarchingCubes cubes;
    cubes.extract(grid, 0.0, mesh, seeds);
    ASSERT_GT(mesh.triangle_count(), 100u);
    expect_closed_and_consistently_wound(mesh);
}

TEST(MarchingCubes, RandomFieldsAcrossBlocksGiveClosedManifoldSurfaces) {
    // Random signs on 2 x 2 x 2 blocks (cells across block boundaries too), an outside
    // layer all round; many seeds, so that two neighbouring cells often share an ambiguous
    // face. Fails with the fan-triangulated table (edges of four triangles).
    for (unsigned seed = 1; seed <= 20; ++seed) {
        std::mt19937 random(seed);
        SparseVoxelGrid grid;
        grid.reset(1.0, 8);
        for (int b = 0; b < 8; ++b) fill_random(grid.block(grid.touch(b & 1, (b >> 1) & 1, b >> 2)), random, 2 * kBlockSize);
        Mesh mesh;
        std::vector<int32_t> seeds;
        MarchingCubes cubes;
        cubes.extract(grid, 0.0, mesh, seeds);
        ASSERT_GT(mesh.triangle_count(), 1000u);
        SCOPED_TRACE("seed " + std::to_string(seed));
        expect_closed_and_consistently_wound(mesh);
    }
}

}  // namespace
