// SPDX-License-Identifier: Apache-2.0
// Marching cubes over the sparse narrow band: every cell whose corners straddle the
// iso-value gets the triangles of its case (marching_cubes_table.h). A corner is inside
// when its field exceeds the iso-value; a corner the band does not reach counts as outside
// (the band stores a negative field there, see SparseVoxelGrid). Vertices sit on lattice
// edges and are shared by the cells around the edge, so the mesh is indexed and closed.
//
// Block by block: the block's corners and the faces of its +x, +y, +z neighbours are
// gathered into a 9^3 array, each row of 9 corners becomes a bit mask of inside corners,
// and a row of 8 cells whose four corner rows are all inside or all outside is skipped
// with one comparison (most of the band). The vertex of a lattice edge is found in a
// per-block table indexed by the edge's first corner and axis, not a hash.
#pragma once

#include <cstdint>
#include <vector>

#include "skinning/mesh.h"
#include "skinning/sparse_voxel_grid.h"
#include "base/geometry.h"

namespace enteron::skinning {

class MarchingCubes {
public:
    // Polygonises the grid's field at `iso` (> 0) into mesh positions (linear
    // interpolation along each edge) and indices; the other vertex buffers are sized but left for the
    // caller. seeds[v] receives, for vertex v, the nearest skeleton point of the inside
    // corner of its edge.
    void extract(const SparseVoxelGrid& grid, double iso, Mesh& mesh, std::vector<int32_t>& seeds);

    // Cells of the last extraction: every cell of every block.
    std::size_t cells_in_band() const { return blocks_ * std::size_t(kBlockCorners); }

private:
    static constexpr uint32_t kNone = ~uint32_t{0};
    // Vertex index of each lattice edge, per block: 3 * kBlockCorners entries (axis-major:
    // axis * kBlockCorners + local index of the edge's first corner), kNone when none.
    std::vector<uint32_t> edge_vertex_;
    std::vector<uint32_t> used_slots_;  // entries of edge_vertex_ set in this extraction
    std::size_t blocks_ = 0;
};

}  // namespace enteron::skinning
