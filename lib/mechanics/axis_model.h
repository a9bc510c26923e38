// SPDX-License-Identifier: Apache-2.0
// The constants of the intestine axis that every effect shares.
#pragma once

#include <cstddef>

#include "spline/catmull_rom.h"
#include "spline/gram_matrix.h"
#include "spline/length_profile.h"

namespace enteron::mechanics {

struct AxisModel {
    std::size_t control_points = 0;
    double rest_segment_length = 0.0;  // l0 = length / (control_points - 1), m
    double linear_density = 0.0;       // mu, kg/m (with a profile: its largest value)
    spline::Ends ends;                 // quadratic at a clamped end (clamped_ends.h)
    // Properties along the length (length_profile.h), or null where they are constant.
    // Owned by the scene, which outlives its effects.
    const spline::LengthProfile* linear_density_profile = nullptr;    // kg/m
    const spline::LengthProfile* stretch_stiffness_profile = nullptr;  // EA, N
    const spline::LengthProfile* bend_stiffness_profile = nullptr;     // EI, N m^2
};

// The mass matrix's Gram scale and profile: M = l0 Gram(value, mu(s)).
inline void add_mass_matrix(const AxisModel& model, numerics::ScalarBandMatrix& mass) {
    const double l0 = model.rest_segment_length;
    if (model.linear_density_profile != nullptr)
        spline::add_gram_matrix(model.control_points, spline::Derivative::value, l0, mass, model.ends,
                                model.linear_density_profile, l0);
    else
        spline::add_gram_matrix(model.control_points, spline::Derivative::value, model.linear_density * l0, mass,
                                model.ends);
}

}  // namespace enteron::mechanics
