// SPDX-License-Identifier: Apache-2.0
// A tool's shaft at one instant (tool.h), as the collision spheres of the bowel meet it: the
// segment tip + s axis (s in [0, 1]) and the reach at which a sphere centre touches it (the
// tool's radius plus the bowel's). Most spheres are far from a tool, so the test is on
// squared distances inside a bounding box and the square root waits for a contact.
// Also the first instant a moving shaft touches a centre (continuous collision), with
// which the tools' proxy moves without passing through the bowel.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/geometry.h"

namespace enteron::collision {

struct Shaft {
    Vec3 tip;
    Vec3 axis;             // tail - tip
    double inverse_axis2;  // 0 for a zero-length shaft (the tip alone)
    double reach;          // the tool's radius plus the bowel's
    // A box around the shaft, reach wide (and a hair more, for rounding): a centre outside
    // it cannot touch.
    Vec3 low, high;

    Shaft(const Vec3& tip_in, const Vec3& tail, double reach_in) : tip(tip_in), axis(tail - tip_in), reach(reach_in) {
        const double axis2 = axis.squaredNorm();
        inverse_axis2 = axis2 > 0.0 ? 1.0 / axis2 : 0.0;
        const double margin = reach * (1.0 + 1e-9);
        low = tip.cwiseMin(tail).array() - margin;
        high = tip.cwiseMax(tail).array() + margin;
    }

    // For a centre p: s of the closest shaft point, d = p minus that point, and |d|^2;
    // true if the sphere reaches into the tool (false, the rest unset, when p is outside
    // the box).
    bool touches(const Vec3& p, double* s, Vec3* d, double* distance2) const {
        if (((p.array() < low.array()) || (p.array() > high.array())).any()) return false;
        closest(p, s, d, distance2);
        return *distance2 < reach * reach;
    }

    // The same without the box: s, d and |d|^2 for any centre.
    void closest(const Vec3& p, double* s, Vec3* d, double* distance2) const {
        const Vec3 rel = p - tip;
        *s = std::clamp(rel.dot(axis) * inverse_axis2, 0.0, 1.0);
        *d = rel - *s * axis;
        *distance2 = d->squaredNorm();
    }

    // The shaft moves by t * motion, t in [0, 1]: the first t at which the centre p comes
    // within `radius` of it (the centre moves by -t motion relative to the shaft), or
    // infinity if it never does. A centre already within `radius` gives 0.
    double first_touch(const Vec3& p, const Vec3& motion, double radius) const {
        const Vec3 origin = p - tip;
        const Vec3 ray = -motion;
        const double radius2 = radius * radius;
        double s, distance2;
        Vec3 d;
        closest(p, &s, &d, &distance2);
        if (distance2 <= radius2) return 0.0;
        double first = std::numeric_limits<double>::infinity();
        // The side of the cylinder: |(o + t r) minus its part along the axis| = radius, the
        // point's axial coordinate within the shaft.
        const double axis2 = axis.squaredNorm();
        if (axis2 > 0.0) {
            const Vec3 o_across = origin - (origin.dot(axis) * inverse_axis2) * axis;
            const Vec3 r_across = ray - (ray.dot(axis) * inverse_axis2) * axis;
            const double a = r_across.squaredNorm();
            const double b = o_across.dot(r_across);
            const double c = o_across.squaredNorm() - radius2;
            const double discriminant = b * b - a * c;
            if (a > 0.0 && discriminant >= 0.0) {
                const double t = (-b - std::sqrt(discriminant)) / a;
                const double along = (origin + t * ray).dot(axis) * inverse_axis2;
                if (t >= 0.0 && t <= 1.0 && along >= 0.0 && along <= 1.0) first = t;
            }
        }
        // The two end caps: spheres of `radius` about the tip and the tail.
        for (const Vec3& centre : {Vec3::Zero().eval(), axis}) {
            const Vec3 o = origin - centre;
            const double a = ray.squaredNorm();
            const double b = o.dot(ray);
            const double c = o.squaredNorm() - radius2;
            const double discriminant = b * b - a * c;
            if (a > 0.0 && discriminant >= 0.0) {
                const double t = (-b - std::sqrt(discriminant)) / a;
                if (t >= 0.0 && t <= 1.0) first = std::min(first, t);
            }
        }
        return first;
    }
};

}  // namespace enteron::collision
