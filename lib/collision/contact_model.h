// The penalty contact law shared by every contact of the bowel (environment, self-contact,
// tools): a normal spring on the penetration depth, a damper that acts only while the
// surfaces approach (so contacts never pull) and fades in over the first `damping_depth` of
// penetration (so a contact starts at zero force: a haptic device feels no step when the
// tool touches), and Coulomb friction regularised below a
// slip speed so it stays smooth. Units: N/m, N s/m, and the friction coefficient.
#pragma once

#include <algorithm>
#include <cmath>

#include "base/geometry.h"

namespace enteron::collision {

struct ContactParameters {
    double stiffness = 500.0;      // N/m per sphere contact
    double damping = 0.5;          // N s/m, on approach only
    double friction = 0.3;         // Coulomb coefficient
    double slip_speed = 0.01;      // m/s: friction is viscous below about this speed
    double damping_depth = 0.0;    // m: the damper reaches full strength at this depth (0: at once);
                                   // the scene sets it from the radius
};

// A bound on the friction's damping mu f_n / slip speed, for contacts up to R / 4 deep
// (the explicit integrators' stable substep; deeper piles rely on the stability guard).
inline double friction_damping_bound(const ContactParameters& p, double radius) {
    return p.friction * p.stiffness * 0.25 * radius / p.slip_speed;
}

// The force on the bowel's sphere for a contact of depth `depth` (> 0) along the unit
// normal n (pointing out of the obstacle), with the sphere's velocity v relative to it.
// Also the linearisation: normal stiffness k, normal damping c (0 when separating) and the
// tangential friction damping c_t, so that H = k n n^T and C = c n n^T + c_t (I - n n^T).
struct ContactForce {
    Vec3 force;           // N
    double normal_force;  // N, >= 0
    double stiffness;
    double damping;
    double friction_damping;
};

inline ContactForce contact_force(const ContactParameters& p, double depth, const Vec3& n, const Vec3& v) {
    ContactForce out{};
    const double vn = v.dot(n);
    const double approach = std::max(0.0, -vn);
    const double fade = depth < p.damping_depth ? depth / p.damping_depth : 1.0;
    out.normal_force = std::max(0.0, p.stiffness * depth + fade * p.damping * approach);
    out.stiffness = p.stiffness;
    out.damping = approach > 0.0 ? fade * p.damping : 0.0;
    const Vec3 vt = v - vn * n;  // tangential velocity
    const double slip = std::sqrt(vt.squaredNorm() + p.slip_speed * p.slip_speed);
    out.friction_damping = p.friction * out.normal_force / slip;
    out.force = out.normal_force * n - out.friction_damping * vt;
    return out;
}

// A contact's part of the implicit system for a substep h, h^2 H + h C, as
// axial n n^T + transverse I: axial = h^2 k + h c - h c_t, transverse = h c_t.
struct ContactLinearization {
    double axial;
    double transverse;
};

inline ContactLinearization contact_linearization(const ContactForce& f, double h) {
    return {h * h * f.stiffness + h * f.damping - h * f.friction_damping, h * f.friction_damping};
}

}  // namespace enteron::collision
