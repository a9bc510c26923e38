// SPDX-License-Identifier: Apache-2.0
// A collision sphere's contact with a tool's shaft (tool_shaft.h), as both tool modes make
// it: where the sphere's centre touches the shaft (s, depth, normal), the contact law's
// Jacobian there (contact_model.h), and how the force changes as the shaft moves rigidly
// with its tip, which the proxy's Newton and the tools' published stiffness need.
#pragma once

#include <cmath>

#include "base/geometry.h"
#include "collision/contact_model.h"
#include "collision/tool_shaft.h"

namespace enteron::collision {

struct ShaftContact {
    ShaftPoint at;    // where on the tool: s along the shaft in [0, 1], w across the blade in [-1, 1] (0 on the shaft)
    Vec3 d;           // the centre minus that point, m
    double distance;  // |d|, m
    double depth;     // the reach minus |d|, m (> 0)
    Vec3 normal;      // out of the tool, towards the centre
};

// The contact of the sphere centred at `center` with the shaft, if it touches it. A centre
// on the shaft's axis is pushed up (+z): any direction will do.
inline bool shaft_contact(const Shaft& shaft, const Vec3& center, ShaftContact* out) {
    double distance2;
    if (!shaft.touches(center, &out->at, &out->d, &distance2)) return false;
    out->distance = std::sqrt(distance2);
    out->depth = shaft.reach - out->distance;
    out->normal = out->distance > 1e-12 ? Vec3(out->d / out->distance) : Vec3::UnitZ();
    return true;
}

// The law's Jacobian at the contact (force `force`, the sphere's velocity relative to the
// tool's point `relative`); on the shaft's axis, where the normal is a choice, the spring
// along it and the dampers of contact_force's linearisation.
inline ContactJacobian shaft_contact_jacobian(const ContactParameters& law, const ShaftContact& contact,
                                              const ContactForce& force, const Vec3& relative) {
    if (contact.distance > 1e-12) return contact_jacobian(law, contact.depth, contact.d, relative);
    const Mat3 nn = contact.normal * contact.normal.transpose();
    return {-law.stiffness * nn, -(force.damping * nn + force.friction_damping * (Mat3::Identity() - nn))};
}

// d(force on the sphere)/d(tip) as the tool moves rigidly with its tip, the sphere held,
// the tool's velocity changing by `velocity_rate` times the tip's move (a proxy's v_p =
// (p - p0) / dt: 1 / dt; velocities held: 0) and its point's velocity with s along
// `axis_velocity` (the tail's velocity minus the tip's) and with w along `side_velocity`.
// Where the nearest point is held (an end, an edge's corner) it moves with the tip; where it
// slides along the axis a, d(d)/d(tip) loses a a^T / |a|^2 and ds/d(tip) = -a^T / |a|^2, and
// across the blade's side e the same with e:
//   d(d)/d(tip) = -(I - [along] a a^T / |a|^2 - [across] e e^T / |e|^2).
inline Mat3 shaft_contact_rate(const ContactJacobian& jacobian, const ShaftContact& contact, const Shaft& shaft,
                               const Vec3& axis_velocity, double velocity_rate, const Vec3& side_velocity = Vec3::Zero()) {
    if (contact.at.slides_along || contact.at.slides_across) {
        Mat3 across = Mat3::Identity();
        Mat3 moving = velocity_rate * Mat3::Identity();
        if (contact.at.slides_along) {
            const Eigen::RowVector3d ds = -shaft.inverse_axis2 * shaft.axis.transpose();
            across += shaft.axis * ds;
            moving += axis_velocity * ds;
        }
        if (contact.at.slides_across) {
            const Eigen::RowVector3d dw = -shaft.inverse_side2 * shaft.blade.side.transpose();
            across += shaft.blade.side * dw;
            moving += side_velocity * dw;
        }
        return -(jacobian.position * across + jacobian.velocity * moving);
    }
    if (velocity_rate == 0.0) return -jacobian.position;
    return -(jacobian.position + velocity_rate * jacobian.velocity);
}

}  // namespace enteron::collision
