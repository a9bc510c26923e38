// Marching cubes over the sparse narrow band: every cell whose corners straddle the
// iso-value gets the triangles of its case (marching_cubes_table.h). A corner the band
// does not reach counts as outside. Vertices sit on lattice edges, shared by the cells
// around the edge through a hash of the edge, so the mesh is indexed and closed.
#pragma once

#include <cstdint>
#include <vector>

#include "skinning/index_hash.h"
#include "skinning/mesh.h"
#include "skinning/sparse_voxel_grid.h"
#include "skinning/vec3.h"

namespace enteron::skinning {

class MarchingCubes {
public:
    // Polygonises the grid's field at `iso` into mesh positions and indices (normals and u
    // are left for the caller). seeds[v] receives, for vertex v, the nearest skeleton point
    // of the inner corner of its edge.
    void extract(const SparseVoxelGrid& grid, double iso, Mesh& mesh, std::vector<int32_t>& seeds);

    std::size_t cells_visited() const { return cells_; }

private:
    IndexHash edge_vertices_;
    std::size_t cells_ = 0;
};

}  // namespace enteron::skinning
