// SPDX-License-Identifier: Apache-2.0
// Where the rings of the convolution skin go along the axis: the level of detail. Evenly
// spaced rings make flat facets where the axis bends; these rings come closer there, so
// that the chord between two rings departs from the tube by at most a tolerance, and stay
// `max_spacing` apart where the axis is straight. The implicit skins' skeletons follow
// the curvature the same way, with a radius of 0: the chord between two skeleton points
// departs from the axis itself by at most the tolerance.
//
// Two rings of radius R, Delta apart on a bend of curvature k: on the outer side the ring
// points are Delta (1 + k R) apart on a circle of radius 1 / k + R, so the straight edge
// between them sags by Delta^2 k (1 + k R) / 8 below the surface (less on the inner side).
// The wanted spacing is then Delta(s) = sqrt(8 e / (k (1 + k R))) for a chord error e,
// clamped to [min_spacing, max_spacing], with k the largest curvature within max_spacing / 2
// of s. The rings are placed at equal steps of the integral of 1 / Delta(s) ds, so their
// count is whole, the ends are rings and no spacing exceeds Delta by more than a rounding.
//
// Levels: to keep the mesh's topology from frame to frame, the ring count can move in
// steps of `level_step` rings: up to the next step above the count the bends need at once
// (so the chord error stays within its bound), down only once a whole step is spare
// (hysteresis: a bowel swaying around a level boundary does not flip between two counts).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "skinning/axis_samples.h"

namespace enteron::skinning {

class RingPlacement {
public:
    // The spacing for a chord error e on a bend of curvature k (1/m) at distance `radius`
    // from the axis: sqrt(8 e / (k (1 + k radius))), within [min_spacing, max_spacing].
    static double spacing_for(double curvature, double radius, double chord_error, double min_spacing,
                              double max_spacing) {
        const double wanted =
            curvature > 0.0 ? std::sqrt(8.0 * chord_error / (curvature * (1.0 + curvature * radius))) : max_spacing;
        return std::clamp(wanted, min_spacing, max_spacing);
    }

    // The rings' places (arc lengths, m, increasing from 0 to the axis length), from `axis`:
    // samples of the axis with their tangents, no more than min_spacing apart (the skin's
    // skeleton samples). level_step > 0: the ring count in steps of that many (above);
    // 0: as many as the bends need. Valid until the next call; allocates only when the
    // ring count grows.
    const std::vector<double>& place(const AxisSamples& axis, double radius, double max_spacing, double min_spacing,
                                     double chord_error, std::size_t level_step);

private:
    std::vector<double> curvature_, density_, arc_lengths_;
    std::size_t level_ = 0;  // intervals between rings at the current level (level_step > 0)
};

}  // namespace enteron::skinning
