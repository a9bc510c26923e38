// SPDX-License-Identifier: Apache-2.0
// Gram matrices of the spline basis: G_jk = scale * sum over segments of the integral over
// t in [0, 1] of w_j(t) w_k(t), for the weights w of one derivative order. They are banded
// (half bandwidth 3) and constant, so they are built once:
//   mass matrix      M   = gram(value,  mu * l0)      kinetic energy 1/2 v^T M v
//   bending matrix   K_b = gram(second, EI / l0^3)    bending energy 1/2 q^T K_b q
//   axial reference  K_a = gram(first,  EA / l0)      the stretch Hessian's axial bound
// where l0 is the rest length of a segment (the parameter maps to arc length as ds = l0 dt).
#pragma once

#include <cstddef>

#include "numerics/banded_matrix.h"
#include "spline/catmull_rom.h"
#include "spline/length_profile.h"

namespace enteron::spline {

// Adds the Gram matrix to `out`, which must already be count x count. Four-point Gauss
// quadrature per segment: exact, since the integrand is a polynomial of degree <= 6.
// With a `profile` (length_profile.h), the integrand is also multiplied by the profile at
// each node's arc length segment_length (segment + t): G_jk = scale * integral of
// f(s) w_j w_k, exact while f is linear over the segment (degree 7).
// `first`: where the spline's points start in `out` (one tube of several, mechanics/axis_model.h).
void add_gram_matrix(std::size_t count, Derivative order, double scale, numerics::ScalarBandMatrix& out,
                     Ends ends = {}, const LengthProfile* profile = nullptr, double segment_length = 0.0,
                     std::size_t first = 0);

}  // namespace enteron::spline
