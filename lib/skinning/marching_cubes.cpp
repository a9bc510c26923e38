// SPDX-License-Identifier: Apache-2.0
#include "skinning/marching_cubes.h"

#include <algorithm>

#include "skinning/frame_buffers.h"
#include "skinning/marching_cubes_table.h"

namespace enteron::skinning {

namespace {

constexpr int kPadded = kBlockSize + 1;  // corners per side of a block's cells
constexpr uint32_t kFullRow = (1u << kPadded) - 1;

constexpr int padded_index(int x, int y, int z) { return x + kPadded * (y + kPadded * z); }

// Which of the block and its +x, +y, +z neighbours (bit 0, 1, 2) holds padded corner
// coordinate (x, y, z), each in [0, kBlockSize].
constexpr int owner_of(int x, int y, int z) {
    return (x == kBlockSize ? 1 : 0) | (y == kBlockSize ? 2 : 0) | (z == kBlockSize ? 4 : 0);
}

}  // namespace

void MarchingCubes::extract(const SparseVoxelGrid& grid, double iso, Mesh& mesh, std::vector<int32_t>& seeds) {
    const auto& table = marching_cubes_table();
    const double voxel = grid.voxel_size();
    mesh.positions.clear();
    mesh.indices.clear();
    seeds.clear();
    blocks_ = grid.block_count();
    const std::size_t slots = 3 * std::size_t(kBlockCorners) * blocks_;
    if (edge_vertex_.size() < slots) {
        reserve_with_headroom(edge_vertex_, slots);
        edge_vertex_.resize(slots, kNone);
    }
    used_slots_.clear();

    float value[kPadded * kPadded * kPadded];
    uint32_t rows[kPadded * kPadded];
    for (std::size_t b = 0; b < blocks_; ++b) {
        const VoxelBlock& block = grid.block(b);
        const auto [bx, by, bz] = block.coordinates;
        // The block and its neighbours at +x, +y, +z and their combinations.
        uint32_t around[8];
        const VoxelBlock* around_block[8];
        for (int c = 0; c < 8; ++c) {
            around[c] = c == 0 ? uint32_t(b) : grid.find(bx + (c & 1), by + ((c >> 1) & 1), bz + ((c >> 2) & 1));
            around_block[c] = around[c] == SparseVoxelGrid::kMissing ? nullptr : &grid.block(around[c]);
        }
        // Gather the 9^3 corners of the block's cells; a missing block is outside (-1).
        for (int z = 0; z < kPadded; ++z)
            for (int y = 0; y < kPadded; ++y) {
                const int yz = owner_of(0, y, z);
                const VoxelBlock* owner = around_block[yz];
                const VoxelBlock* beyond = around_block[yz | 1];
                float* row = &value[padded_index(0, y, z)];
                const std::size_t local = SparseVoxelGrid::local_index(0, y % kBlockSize, z % kBlockSize);
                if (owner != nullptr)
                    std::copy_n(&owner->field[local], kBlockSize, row);
                else
                    std::fill_n(row, kBlockSize, -1.0f);
                row[kBlockSize] = beyond != nullptr ? beyond->field[local] : -1.0f;
                uint32_t bits = 0;
                for (int x = 0; x < kPadded; ++x) bits |= uint32_t(double(row[x]) > iso) << x;
                rows[y + kPadded * z] = bits;
            }

        const int32_t gx0 = bx * kBlockSize, gy0 = by * kBlockSize, gz0 = bz * kBlockSize;
        for (int z = 0; z < kBlockSize; ++z)
            for (int y = 0; y < kBlockSize; ++y) {
                const uint32_t r0 = rows[y + kPadded * z], r1 = rows[y + 1 + kPadded * z];
                const uint32_t r2 = rows[y + kPadded * (z + 1)], r3 = rows[y + 1 + kPadded * (z + 1)];
                if ((r0 | r1 | r2 | r3) == 0 || (r0 & r1 & r2 & r3) == kFullRow) continue;
                for (int x = 0; x < kBlockSize; ++x) {
                    const uint32_t mask = ((r0 >> x) & 3) | (((r1 >> x) & 3) << 2) | (((r2 >> x) & 3) << 4) |
                                          (((r3 >> x) & 3) << 6);
                    if (mask == 0 || mask == 255) continue;
                    const MarchingCubesCase& entry = table[mask];
                    uint32_t edge_vertex[12];
                    uint16_t have = 0;
                    for (int t = 0; t < 3 * entry.triangle_count; ++t) {
                        const int e = entry.edges[std::size_t(t)];
                        if (have & (1u << e)) continue;
                        have = uint16_t(have | (1u << e));
                        const int c0 = kEdgeCorners[std::size_t(e)][0], axis = e / 4;
                        // First corner of the edge, in padded coordinates, and its owner.
                        const int ex = x + (c0 & 1), ey = y + ((c0 >> 1) & 1), ez = z + ((c0 >> 2) & 1);
                        const int ox = ex + (axis == 0), oy = ey + (axis == 1), oz = ez + (axis == 2);
                        const uint32_t owner = around[owner_of(ex, ey, ez)];
                        uint32_t* slot = nullptr;
                        if (owner != SparseVoxelGrid::kMissing) {
                            slot = &edge_vertex_[(3 * std::size_t(owner) + std::size_t(axis)) * kBlockCorners +
                                                 SparseVoxelGrid::local_index(ex % kBlockSize, ey % kBlockSize,
                                                                              ez % kBlockSize)];
                            if (*slot != kNone) {
                                edge_vertex[e] = *slot;
                                continue;
                            }
                        }
                        // New vertex: linear interpolation of the field along the edge (a
                        // corner outside the band, stored as -1, counts as 0).
                        const double fa = std::max(0.0f, value[padded_index(ex, ey, ez)]);
                        const double fb = std::max(0.0f, value[padded_index(ox, oy, oz)]);
                        double w = fb != fa ? (iso - fa) / (fb - fa) : 0.5;
                        w = std::clamp(w, 0.0, 1.0);
                        double p[3] = {double(gx0 + ex) * voxel, double(gy0 + ey) * voxel, double(gz0 + ez) * voxel};
                        p[axis] += w * voxel;
                        const auto index = uint32_t(seeds.size());
                        mesh.positions.insert(mesh.positions.end(), {float(p[0]), float(p[1]), float(p[2])});
                        // The inside corner always lies in an existing block.
                        const bool first_inside = fa > iso;
                        const int ix = first_inside ? ex : ox, iy = first_inside ? ey : oy, iz = first_inside ? ez : oz;
                        const VoxelBlock* inside = around_block[owner_of(ix, iy, iz)];
                        seeds.push_back(nearest_point(inside->nearest[SparseVoxelGrid::local_index(
                            ix % kBlockSize, iy % kBlockSize, iz % kBlockSize)]));
                        edge_vertex[e] = index;
                        // An edge whose first corner's block is missing is not shared: never
                        // the case in a band wider than a voxel beyond the surface.
                        if (slot != nullptr) {
                            *slot = index;
                            used_slots_.push_back(uint32_t(slot - edge_vertex_.data()));
                        }
                    }
                    for (int t = 0; t < 3 * entry.triangle_count; ++t)
                        mesh.indices.push_back(edge_vertex[entry.edges[std::size_t(t)]]);
                }
            }
    }
    // Leave the edge table empty for the next extraction.
    for (uint32_t slot : used_slots_) edge_vertex_[slot] = kNone;
    mesh.resize_vertices(seeds.size());
}

}  // namespace enteron::skinning
