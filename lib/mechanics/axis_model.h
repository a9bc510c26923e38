// SPDX-License-Identifier: Apache-2.0
// The constants of the intestine axis that every effect shares.
//
// The axis is one or several tubes, each its own spline (its own ends: no segment spans two
// tubes), their control points back to back in one state: tube k owns the points
// [first_k, first_k + n_k). Every matrix is then block-banded with no coupling between
// tubes, so the banded solve is unchanged (a zero band between blocks).
#pragma once

#include <cstddef>
#include <vector>

#include "spline/catmull_rom.h"
#include "spline/gram_matrix.h"
#include "spline/length_profile.h"

namespace enteron::mechanics {

// One tube of the axis.
struct TubeModel {
    std::size_t first = 0;             // its first control point in the state
    std::size_t control_points = 0;    // n_k >= 4
    double rest_segment_length = 0.0;  // l0 = length / (n_k - 1), m
    double linear_density = 0.0;       // mu, kg/m (with a profile: its largest value)
    spline::Ends ends;                 // quadratic at a clamped end (clamped_ends.h)
    // Properties along the length (length_profile.h), or null where they are constant.
    // Owned by the scene, which outlives its effects.
    const spline::LengthProfile* linear_density_profile = nullptr;    // kg/m
    const spline::LengthProfile* stretch_stiffness_profile = nullptr;  // EA, N
    const spline::LengthProfile* bend_stiffness_profile = nullptr;     // EI, N m^2
    // This tube's constant EA (N) and EI (N m^2) where it has no profile; < 0: the value
    // its effect was made with (the same for every such tube).
    double stretch_stiffness = -1.0;
    double bend_stiffness = -1.0;

    // EA or EI of this tube where it is constant: its own, or the effect's `shared`.
    static double own_or(double own, double shared) { return own >= 0.0 ? own : shared; }
};

struct AxisModel {
    std::size_t control_points = 0;  // of every tube
    // An axis of one tube (tubes empty): that tube's constants, as TubeModel's.
    double rest_segment_length = 0.0;
    double linear_density = 0.0;
    spline::Ends ends;
    const spline::LengthProfile* linear_density_profile = nullptr;
    const spline::LengthProfile* stretch_stiffness_profile = nullptr;
    const spline::LengthProfile* bend_stiffness_profile = nullptr;
    // Several tubes: each one, in the order of their points (control_points their sum); the
    // one-tube fields above are then not read.
    std::vector<TubeModel> tubes;

    // Every tube: `tubes`, or the one the fields above describe.
    std::vector<TubeModel> tube_list() const {
        if (!tubes.empty()) return tubes;
        return {TubeModel{0, control_points, rest_segment_length, linear_density, ends, linear_density_profile,
                          stretch_stiffness_profile, bend_stiffness_profile, -1.0, -1.0}};
    }
};

// Adds a Gram matrix of every tube into `out` (control_points square), each tube's block at
// its first point: scale_of(tube) and profile_of(tube) give its scale and profile (null:
// constant), read at the tube's own arc length.
template <class Scale, class Profile>
void add_tube_gram_matrices(const AxisModel& model, spline::Derivative order, numerics::ScalarBandMatrix& out,
                            Scale&& scale_of, Profile&& profile_of) {
    for (const TubeModel& tube : model.tube_list()) {
        const spline::LengthProfile* profile = profile_of(tube);
        spline::add_gram_matrix(tube.control_points, order, scale_of(tube, profile != nullptr), out, tube.ends,
                                profile, tube.rest_segment_length, tube.first);
    }
}

// The mass matrix's Gram scale and profile: M = l0 Gram(value, mu(s)), tube by tube.
inline void add_mass_matrix(const AxisModel& model, numerics::ScalarBandMatrix& mass) {
    add_tube_gram_matrices(
        model, spline::Derivative::value, mass,
        [](const TubeModel& tube, bool profiled) {
            return profiled ? tube.rest_segment_length : tube.linear_density * tube.rest_segment_length;
        },
        [](const TubeModel& tube) { return tube.linear_density_profile; });
}

}  // namespace enteron::mechanics
