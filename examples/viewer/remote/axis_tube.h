// SPDX-License-Identifier: Apache-2.0
// The bowel as a tube of radius R around its axis polyline, for a remote session whose
// server sends no mesh (enteron-lcm-server's default, --mesh-hz 0): scene_state_t carries
// the axis sampled evenly in arc length and the radius, which is all a tube needs.
#pragma once

#include <cstdint>
#include <vector>

namespace viewer {

// A triangle mesh as ent_mesh_view describes it, owned.
struct MeshArrays {
    std::vector<float> positions_m, normals, axis_u;  // 3, 3 and 1 per vertex
    std::vector<std::uint32_t> indices;               // counter-clockwise seen from outside
};

// Rings of `sides` vertices around each axis point (x y z per point, at least 2 points),
// oriented by parallel transport so that the tube does not twist, closed by a flat cap at
// each end. Render thread; reuses out's storage.
void make_axis_tube(const std::vector<double>& axis_m, double radius_m, int sides, MeshArrays& out);

}  // namespace viewer
