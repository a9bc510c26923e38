// SPDX-License-Identifier: Apache-2.0
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

// The exact derivatives of contact_force for a sphere whose centre is at d from the closest
// point of the other surface (depth = reach - |d|, n = d / |d|, |d| > 0), its velocity v
// relative to it: position = d(force) / d(d) with v held, velocity = d(force) / d(v) with d
// held. Where the law has a kink (the damper's and the normal force's switches) the side the
// contact is on. The tools' stiffness and their proxy's solve use them; the implicit system
// keeps the symmetric approximation of contact_linearization.
struct ContactJacobian {
    Mat3 position;  // N/m
    Mat3 velocity;  // N s/m
};

inline ContactJacobian contact_jacobian(const ContactParameters& p, double depth, const Vec3& d, const Vec3& v) {
    ContactJacobian out{Mat3::Zero(), Mat3::Zero()};
    const double length = d.norm();
    const Vec3 n = d / length;
    const double vn = v.dot(n);
    const double approach = std::max(0.0, -vn);
    const double fade = depth < p.damping_depth ? depth / p.damping_depth : 1.0;
    const double normal_force = p.stiffness * depth + fade * p.damping * approach;
    if (!(normal_force > 0.0)) return out;  // the contact pushes nothing: no force around it
    const Mat3 across = (Mat3::Identity() - n * n.transpose()) / length;  // dn/dd
    const Vec3 vt = v - vn * n;
    // d(vn)/dd = v^T dn/dd; d(vt)/dd = -(n d(vn)/dd + vn dn/dd).
    const Eigen::RowVector3d dvn_dd = v.transpose() * across;
    const Mat3 dvt_dd = -(n * dvn_dd + vn * across);
    // d(normal force)/dd: the spring on the depth, the damper on its fade and on the approach.
    Eigen::RowVector3d dfn_dd = -p.stiffness * n.transpose();
    if (depth < p.damping_depth) dfn_dd += -(approach * p.damping / p.damping_depth) * n.transpose();
    if (vn < 0.0) dfn_dd += -(fade * p.damping) * dvn_dd;
    const Eigen::RowVector3d dfn_dv = vn < 0.0 ? Eigen::RowVector3d(-(fade * p.damping) * n.transpose())
                                               : Eigen::RowVector3d::Zero();
    // Friction -mu f_n vt / slip, slip = sqrt(|vt|^2 + s^2).
    const double slip = std::sqrt(vt.squaredNorm() + p.slip_speed * p.slip_speed);
    const double mu = p.friction;
    const Mat3 dvt_dv = Mat3::Identity() - n * n.transpose();
    const Eigen::RowVector3d dslip_dd = (vt.transpose() * dvt_dd) / slip;
    const Eigen::RowVector3d dslip_dv = (vt.transpose() * dvt_dv) / slip;
    out.position = n * dfn_dd + normal_force * across -
                   (mu / slip) * (vt * dfn_dd + normal_force * dvt_dd - (normal_force / slip) * vt * dslip_dd);
    out.velocity = n * dfn_dv - (mu / slip) * (vt * dfn_dv + normal_force * dvt_dv -
                                               (normal_force / slip) * vt * dslip_dv);
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
