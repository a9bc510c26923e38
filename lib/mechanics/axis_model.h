// The constants of the intestine axis that every effect shares.
#pragma once

#include <cstddef>

namespace enteron::mechanics {

struct AxisModel {
    std::size_t control_points = 0;
    double rest_segment_length = 0.0;  // l0 = length / (control_points - 1), m
    double linear_density = 0.0;       // mu, kg/m
};

}  // namespace enteron::mechanics
