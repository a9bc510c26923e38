// SPDX-License-Identifier: Apache-2.0
// Where two folds meet: the contact surface and the bulge around it, along one ray of a
// skin. Cani (Gascuel) 1993, "An implicit formulation for precise contact modeling between
// flexible solids": where two implicit volumes would interpenetrate, each surface is
// replaced by the surface where their fields are equal, and just outside it a propagation
// zone swells the surface so that the volume pushed out of the contact reappears around
// it. With local convolution "the other fold" is the axis outside a surface point's own
// stretch of tube (Angelidis, Jepp and Cani 2002; fold_contacts.h).
//
// The field of each fold F is that of the tube of its radius R_F around its axis, as a
// normalised distance o_F(p) = r_F(p) / R_F (r_F: the distance from p to F's axis): the
// surface every skin approximates, to within its radius error. A surface point of fold A
// lies on A's ray from its axis point c in direction d (unit, normal to the axis), at
// distance t; t0 is where the skin puts it when nothing touches (its free radius). The
// other folds are measured from A's free surface,
//     x(p) = (R_A / t0) min_B o_B(p) - 1,
// and the composition of the fields reads, along the ray (u = t / t0 - 1),
//     u = D(x(c + t d)),   D(x) = x                     x <= 0       the contact
//                               = x (1 - x / w)^2        0 <= x <= w  the bulge
//                               = 0                      x >= w       untouched
//  - the contact (x <= 0): t / R_A = r_B / R_B, the same surface for both folds (B's rays
//    solve t_B / R_B = r_A / R_A), so their skins meet on it with neither overlap nor gap;
//    for equal radii it is the plane (or saddle) half-way between the two axes;
//  - the bulge (0 <= x <= w): the surface swells by at most 4 w / 27 of t0 (at x = w / 3),
//    C1 at both ends (D'(0) = 1 continues the contact surface, D(w) = D'(w) = 0), and never
//    crosses the contact surface (D(x) <= x: A's point stays nearer A, in radii);
//  - w, how far from the other fold (in units of its radius) the bulge reaches, is chosen
//    per ring so that the ring's cross-section keeps its area (ring_contacts.h), at most
//    kMaxBulgeReach: the bulge is at most 4 kMaxBulgeReach / 27 of the free radius high.
// D is continuous in x and w, so the surface moves continuously as contacts come and go.
//
// Along a ray the other fold's level is taken as linear in u around the point where it
// was measured, x = x0 + G u with G = dx/du (ContactRay); both branches then have closed
// forms or a two-step Newton, which is all a ring solve can afford per ray and bulge trial.
#pragma once

#include <algorithm>

namespace enteron::skinning {

inline constexpr double kMaxBulgeReach = 0.75;  // w at most: the bulge at most 11 % of the free radius high

// D(x) for a bulge reaching w (> 0), and its derivative dD/dx.
inline double contact_deformation(double x, double w, double* slope) {
    if (x <= 0.0) {
        *slope = 1.0;
        return x;
    }
    if (x >= w) {
        *slope = 0.0;
        return 0.0;
    }
    const double a = 1.0 - x / w;
    *slope = a * (1.0 - 3.0 * x / w);
    return x * a * a;
}

// The other folds as seen along one ray: x = x0 + G u near the measured point.
struct ContactRay {
    double x0 = 1e30;  // x at u = 0 (the free radius): <= 0 inside the contact
    double G = 0.0;    // dx/du = R_A d . grad o_B, in [-R_A / R_B, R_A / R_B]

    bool touches() const { return x0 <= 0.0; }

    // u of the contact surface on this ray (x0 <= 0): u = x0 + G u. (G near 1 would be a ray
    // leaving the other fold from inside it, which two tubes cannot make; kept finite.)
    double contact_u() const { return x0 / std::max(1.0 - G, 0.25); }

    // u of the bulge reaching w on this ray (x0 > 0): u = D(x0 + G u) by two Newton steps
    // from u = 0. The residual's slope 1 - G D' stays above 1/4 (|G| <= 1 or so, D' in
    // [-1/3, 1], and D' = 1 only at x = 0, where D = 0).
    double bulge_u(double w) const {
        if (!(x0 < w)) return 0.0;
        double u = 0.0;
        for (int step = 0; step < 2; ++step) {
            double slope = 0.0;
            const double d = contact_deformation(x0 + G * u, w, &slope);
            u -= (u - d) / std::max(1.0 - G * slope, 0.25);
        }
        return std::max(u, 0.0);
    }
};

}  // namespace enteron::skinning
