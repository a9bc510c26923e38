// SPDX-License-Identifier: Apache-2.0
#include "mechanics/mesentery_root.h"

#include <algorithm>

namespace enteron::mechanics {

Vec3 point_along_root(const std::pmr::vector<Vec3>& points, double t) {
    if (points.size() == 2) return points[0] + t * (points[1] - points[0]);
    double length = 0.0;
    for (std::size_t k = 1; k < points.size(); ++k) length += (points[k] - points[k - 1]).norm();
    // The distance still to walk from the start of each segment.
    double remaining = std::clamp(t, 0.0, 1.0) * length;
    for (std::size_t k = 1; k < points.size(); ++k) {
        const Vec3 segment = points[k] - points[k - 1];
        const double segment_length = segment.norm();
        if (remaining <= segment_length && segment_length > 0.0)
            return points[k - 1] + (remaining / segment_length) * segment;
        remaining -= segment_length;
    }
    return points.back();  // t = 1, past the last segment by rounding
}

}  // namespace enteron::mechanics
