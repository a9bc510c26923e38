// SPDX-License-Identifier: Apache-2.0
// The mesenteric root as a polyline: the line at the back of the abdomen from which the
// mesentery fans out (the small bowel's runs about 15 cm obliquely, from the
// duodenojejunal flexure to the ileocaecal junction). A point of it is named by t, the
// fraction of the polyline's length from its first point (0) to its last (1).
#pragma once

#include <memory_resource>
#include <vector>

#include "base/geometry.h"

namespace enteron::mechanics {

// The point at fraction t (0..1) of the length of the polyline `points` (two or more). On
// the segment of two points it is start + t (end - start) whatever their distance (the root
// may be one point); along more, t x the length is walked segment by segment.
Vec3 point_along_root(const std::pmr::vector<Vec3>& points, double t);

}  // namespace enteron::mechanics
