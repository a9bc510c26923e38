// SPDX-License-Identifier: Apache-2.0
// The constants of the intestine axis that every effect shares.
#pragma once

#include <cstddef>

#include "spline/catmull_rom.h"

namespace enteron::mechanics {

struct AxisModel {
    std::size_t control_points = 0;
    double rest_segment_length = 0.0;  // l0 = length / (control_points - 1), m
    double linear_density = 0.0;       // mu, kg/m
    spline::Ends ends;                 // quadratic at a clamped end (clamped_ends.h)
};

}  // namespace enteron::mechanics
