// SPDX-License-Identifier: Apache-2.0
#include "scene/pin_spans.h"

#include <algorithm>
#include <cmath>

namespace enteron::scene {

ControlPointRange control_points_in(const PinSpan& span, std::size_t control_points, double length) {
    constexpr double kRounding = 1e-9;  // of a spacing: a span ending on a point holds it
    const double spacing = length / static_cast<double>(control_points - 1);
    const double last_index = static_cast<double>(control_points - 1);
    const double first = std::max(0.0, std::ceil(span.from / spacing - kRounding));
    const double last = std::min(last_index, std::floor(span.to / spacing + kRounding));
    if (!(first <= last)) return {};
    return {static_cast<uint32_t>(first), static_cast<uint32_t>(last)};
}

}  // namespace enteron::scene
