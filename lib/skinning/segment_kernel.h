// SPDX-License-Identifier: Apache-2.0
// The convolution of a line segment with the kernel 1/r^3, in closed form (Cani and Hornus,
// "Subdivision-curve primitives", 2001). For a point P whose foot on the segment's line is
// H, at distance h = d(P, H), with theta the angle seen from P between PH and the segment
// point at signed abscissa x from H (tan theta = x / h):
//   integral over the segment of ds / r(s)^3 = integral of cos(theta) d(theta) / h^2
//                                            = (sin theta_B - sin theta_A) / h^2,
// with sin theta = x / sqrt(h^2 + x^2) at each end. Exact, no quadrature: the field of a
// polyline is a sum over its segments and has no bumps at the joints.
#pragma once

#include <algorithm>
#include <cmath>

#include "base/geometry.h"

namespace enteron::skinning {

// Field of segment [a, b] at p. Zero for a degenerate segment.
inline double segment_field(Vec3 p, Vec3 a, Vec3 b) {
    const Vec3 d = b - a;
    const double length2 = d.squaredNorm();
    if (!(length2 > 0.0)) return 0.0;
    const double length = std::sqrt(length2);
    const Vec3 e = (1.0 / length) * d;
    const Vec3 w = p - a;
    const double xa = -w.dot(e);  // abscissa of a from the foot H (b is at xa + length)
    const Vec3 off_line = w + xa * e;
    // P on the line itself (never on a surface of radius R > 0): keep the field finite.
    const double h_squared = std::max(off_line.squaredNorm(), 1e-12 * length2);
    const double xb = xa + length;
    return (xb / std::sqrt(h_squared + xb * xb) - xa / std::sqrt(h_squared + xa * xa)) / h_squared;
}

}  // namespace enteron::skinning
