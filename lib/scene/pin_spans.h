// SPDX-License-Identifier: Apache-2.0
// The control points a pinned span of the bowel holds (pinned.spans, scene_config.h): those
// whose rest arc length s_i = i L / (n - 1) (control points are spread evenly along the
// axis at rest) lies in [from, to], a hair of rounding spared at both ends.
#pragma once

#include <cstddef>
#include <cstdint>

#include "scene/scene_config.h"

namespace enteron::scene {

// Control points first .. last (inclusive); empty when first > last.
struct ControlPointRange {
    uint32_t first = 1;
    uint32_t last = 0;
    bool empty() const { return first > last; }
};

ControlPointRange control_points_in(const PinSpan& span, std::size_t control_points, double length);

}  // namespace enteron::scene
