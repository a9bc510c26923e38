// SPDX-License-Identifier: Apache-2.0
// The collision spheres of a remote session: scene_state_t carries the axis sampled evenly
// in arc length, not the spheres' centres (which are the axis sampled evenly at the
// spheres' count, ent_scene_axis). The polyline resampled evenly along its length gives
// them to within the polyline's chord error, far below the sphere radius R for the
// server's axis (hundreds of points).
#pragma once

#include <cstdint>
#include <vector>

namespace viewer {

// count points (>= 2) evenly spaced along the length of the polyline (x y z per point, at
// least 2 points), its first and last points included, into out (x y z each). Render
// thread; reuses out's storage. Fewer than 2 input points: out empty.
void resample_evenly(const std::vector<double>& polyline_m, std::uint32_t count, std::vector<double>& out);

}  // namespace viewer
