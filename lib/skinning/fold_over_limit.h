// SPDX-License-Identifier: Apache-2.0
// No folded-over triangles: how far a ring's ray may reach before it passes its
// neighbouring ring.
//
// Rings stand in the normal planes of the axis. At a bend of radius rho the planes of two
// neighbouring rings meet on the bend's axis, rho from the centre line on the inner side:
// a vertex placed farther than that along a ray towards the inside lies beyond the next
// ring's plane, the quads between the two rings turn inside out, and the surface folds
// over (the tube's artefact at bends tighter than R, and any ring skin's wherever a bulge
// or a tight bend takes a vertex there). A vertex stays on its own side if it is nearer to
// its own ring's centre c than to the neighbour's n (the plane half-way between the two
// centres, through the bend's axis):
//     |c + t d - c| <= |c + t d - n|   <=>   t <= |n - c|^2 / (2 d . (n - c))   when d . (n - c) > 0.
// The limit is approached smoothly, with L = 0.99 limit, as L r / (1 + r^64)^(1/64), r = t / L:
// below 0.9 of the limit a ray loses under 0.005 % of its length (a bend of radius 1.1 R
// keeps its inner side at R), at the limit it stops at 0.98 of it, and however long it
// was it stays below 0.99 of it (in floating point too), so the two rings' vertices never
// cross even on a bend tighter than R
// (there the inner side of the tube becomes a crease along the bend's axis, as the tube
// of radius R around such an axis really is). Continuous in t and in the limit: a bend
// tightening from frame to frame moves the vertices smoothly.
#pragma once

#include <cmath>
#include <limits>

#include "base/geometry.h"

namespace enteron::skinning {

// The longest ray from ring centre c along unit d that stays nearer c than the
// neighbouring ring centre n; infinity when d does not point towards n's side.
inline double fold_over_limit(const Vec3& c, const Vec3& d, const Vec3& n) {
    const Vec3 towards = n - c;
    const double approach = d.dot(towards);
    return approach > 0.0 ? towards.squaredNorm() / (2.0 * approach) : std::numeric_limits<double>::infinity();
}

// t kept smoothly below 0.99 `limit` (> 0): L r / (1 + r^64)^(1/64), L = 0.99 limit, r = t / L.
inline double below_fold_over_limit(double t, double limit) {
    if (!(limit < std::numeric_limits<double>::infinity())) return t;
    const double L = 0.99 * limit;
    const double r = t / L, r2 = r * r, r4 = r2 * r2, r8 = r4 * r4, r16 = r8 * r8, r32 = r16 * r16;
    if (r32 < 1e-7) return t;  // (1 + r^64)^(1/64) - 1 < 1e-16
    return L * (r / std::pow(1.0 + r32 * r32, 1.0 / 64.0));
}

}  // namespace enteron::skinning
