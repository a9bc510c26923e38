// SPDX-License-Identifier: Apache-2.0
// The grasp of a tool (tools_force.h): a tension-only spring-damper of rest length r from the
// held axis point p, moving at v, to the tool's tip x, moving at v_x (the proxy's tip in proxy
// mode). Its force on the bowel, with n the unit direction from p to x:
//
//   f = k (|x - p| - r) n + c (v_x - v)     while |x - p| > r (taut); 0 when slack
//
// so a grasp starts and ends without a jolt: the rest length starts where the held point
// was when grasped and closes at kClosingSpeed to the tool's radius plus the bowel's, where
// the held point sits on the tool's surface and its contact neither pushes nor pulls. With
// the stretch ratio s = r / |x - p|, its Jacobian blocks are
//
//   H = -df/dp = a n n^T + b I,   a = k s,   b = k (1 - s)       (the implicit system's stiffness)
//   C = -df/dv = c I                                              (its damping)
//   df/dx, the tip's velocity changing by rate times its move  = H + c rate I
//
// (the proxy's v_x = (x - x0) / dt moves with x: rate 1 / dt), its part of the implicit system
// for a substep h is h^2 H + h C = h^2 a n n^T + (h c + h^2 b) I, and it stores the energy
// 1/2 k (|x - p| - r)^2 while taut.
#pragma once

#include <algorithm>

#include "base/geometry.h"
#include "collision/contact_model.h"

namespace enteron::collision {

struct GraspLaw {
    double stiffness = 200.0;  // k, N/m
    double damping = 2.0;      // c, N s/m
};

// How fast a grasp draws the held point in to the tool's surface, m/s: a grasp taken from a
// distance starts slack (no jolt for the device) and tightens by at most k x 0.05 mm a
// millisecond (docs/haptics.md, "Force continuity").
constexpr double kGraspClosingSpeed = 0.05;

// The rest length `elapsed` seconds after it was `rest` (m), closing to `surface` (the
// tool's radius plus the bowel's, m).
inline double grasp_rest(double rest, double surface, double elapsed) {
    return std::max(surface, rest - kGraspClosingSpeed * elapsed);
}

// The spring at one instant: its force and what its Jacobian blocks are made of.
struct GraspSpring {
    bool taut = false;
    Vec3 force = Vec3::Zero();       // f on the bowel, N
    Vec3 direction = Vec3::UnitZ();  // n
    double axial = 0.0;              // a, N/m
    double isotropic = 0.0;          // b, N/m
};

inline GraspSpring grasp_spring(const GraspLaw& law, double rest, const Vec3& tip, const Vec3& tip_velocity,
                                const Vec3& point, const Vec3& velocity) {
    GraspSpring spring;
    const Vec3 gap = tip - point;
    const double length = gap.norm();
    if (!(length > rest)) return spring;
    spring.taut = true;
    const Vec3& n = spring.direction = gap / length;
    spring.axial = law.stiffness * rest / length;
    spring.isotropic = law.stiffness * (1.0 - rest / length);
    spring.force = law.stiffness * (length - rest) * n + law.damping * (tip_velocity - velocity);
    return spring;
}

// H = a n n^T + b I.
inline Mat3 grasp_stiffness(const GraspSpring& spring) {
    return spring.axial * outer(spring.direction) + spring.isotropic * Mat3::Identity();
}

// df/dx = H + c rate I, the tip's velocity changing by `velocity_rate` times its move.
inline Mat3 grasp_tip_rate(const GraspSpring& spring, const GraspLaw& law, double velocity_rate) {
    const Vec3& n = spring.direction;
    return spring.axial * n * n.transpose() + (spring.isotropic + law.damping * velocity_rate) * Mat3::Identity();
}

// h^2 H + h C as axial n n^T + transverse I (contact_model.h's form).
inline ContactLinearization grasp_linearization(const GraspSpring& spring, const GraspLaw& law, double h) {
    return {h * h * spring.axial, h * law.damping + h * h * spring.isotropic};
}

// The energy stored with the tip at x and the held point at p, J.
inline double grasp_energy(const GraspLaw& law, double rest, const Vec3& tip, const Vec3& point) {
    const double stretch = std::max(0.0, (tip - point).norm() - rest);
    return 0.5 * law.stiffness * stretch * stretch;
}

}  // namespace enteron::collision
