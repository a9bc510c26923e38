#include "skinning/marching_cubes.h"

#include "skinning/marching_cubes_table.h"

namespace enteron::skinning {

void MarchingCubes::extract(const SparseVoxelGrid& grid, double iso, Mesh& mesh, std::vector<int32_t>& seeds) {
    const auto& table = marching_cubes_table();
    const double voxel = grid.voxel_size();
    const VoxelCorner outside{0.0f, 0.0f, -1};
    mesh.positions.clear();
    mesh.indices.clear();
    seeds.clear();
    edge_vertices_.clear(mesh.u.size() + 1024);
    cells_ = 0;

    for (std::size_t b = 0; b < grid.block_count(); ++b) {
        const VoxelBlock& block = grid.block(b);
        const auto [bx, by, bz] = block.coordinates;
        // The block and its neighbours at +x, +y, +z and their combinations.
        const VoxelBlock* around[8];
        for (int c = 0; c < 8; ++c)
            around[c] = c == 0 ? &block : grid.find(bx + (c & 1), by + ((c >> 1) & 1), bz + ((c >> 2) & 1));

        for (int z = 0; z < kBlockSize; ++z)
            for (int y = 0; y < kBlockSize; ++y)
                for (int x = 0; x < kBlockSize; ++x) {
                    const VoxelCorner* corner[8];
                    int mask = 0;
                    for (int c = 0; c < 8; ++c) {
                        int cx = x + (c & 1), cy = y + ((c >> 1) & 1), cz = z + ((c >> 2) & 1);
                        const int which = (cx == kBlockSize ? 1 : 0) | (cy == kBlockSize ? 2 : 0) | (cz == kBlockSize ? 4 : 0);
                        const VoxelBlock* owner = around[which];
                        if (owner == nullptr) {
                            corner[c] = &outside;
                        } else {
                            cx %= kBlockSize;
                            cy %= kBlockSize;
                            cz %= kBlockSize;
                            corner[c] = &owner->corners[SparseVoxelGrid::local_index(cx, cy, cz)];
                        }
                        if (corner[c]->nearest >= 0 && double(corner[c]->field) > iso) mask |= 1 << c;
                    }
                    if (mask == 0 || mask == 255) continue;
                    ++cells_;
                    const int32_t gx = bx * kBlockSize + x, gy = by * kBlockSize + y, gz = bz * kBlockSize + z;
                    const MarchingCubesCase& entry = table[std::size_t(mask)];
                    uint32_t edge_vertex[12];
                    bool have[12] = {};
                    for (int t = 0; t < 3 * entry.triangle_count; ++t) {
                        const int e = entry.edges[std::size_t(t)];
                        if (!have[e]) {
                            const int c0 = kEdgeCorners[std::size_t(e)][0], c1 = kEdgeCorners[std::size_t(e)][1];
                            const int axis = e / 4;
                            const uint64_t key = (SparseVoxelGrid::pack(gx + (c0 & 1), gy + ((c0 >> 1) & 1),
                                                                        gz + ((c0 >> 2) & 1))
                                                  << 2) | uint64_t(axis);
                            bool inserted = false;
                            const auto next = uint32_t(seeds.size());
                            edge_vertex[e] = edge_vertices_.find_or_insert(key, next, &inserted);
                            have[e] = true;
                            if (inserted) {
                                const VoxelCorner& a = *corner[c0];
                                const VoxelCorner& b2 = *corner[c1];
                                const double fa = a.nearest >= 0 ? a.field : 0.0, fb = b2.nearest >= 0 ? b2.field : 0.0;
                                double w = fb != fa ? (iso - fa) / (fb - fa) : 0.5;
                                w = w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w);
                                const double px = (gx + (c0 & 1)) * voxel, py = (gy + ((c0 >> 1) & 1)) * voxel,
                                             pz = (gz + ((c0 >> 2) & 1)) * voxel;
                                double p[3] = {px, py, pz};
                                p[axis] += w * voxel;
                                mesh.positions.insert(mesh.positions.end(), {float(p[0]), float(p[1]), float(p[2])});
                                // The inside corner always has a skeleton point.
                                seeds.push_back(fa > iso && a.nearest >= 0 ? a.nearest : b2.nearest);
                            }
                        }
                    }
                    for (int t = 0; t < 3 * entry.triangle_count; ++t)
                        mesh.indices.push_back(edge_vertex[entry.edges[std::size_t(t)]]);
                }
    }
    const std::size_t n = seeds.size();
    mesh.normals.resize(3 * n);
    mesh.u.resize(n);
}

}  // namespace enteron::skinning
