// SPDX-License-Identifier: Apache-2.0
// A tool's shape at one instant (tool.h), as the collision spheres of the bowel meet it: the
// shaft, the segment tip + s axis (s in [0, 1]), and, for a retractor, a flat blade at its
// tip: the rectangle tip + s axis + w side (s in [0, blade], w in [-1, 1]; side the half
// width across the tool's local x), the shaft's first `blade` of its length widened. Both are
// swept by the reach at which a sphere centre touches them (the tool's radius plus the
// bowel's): a capsule, and a rounded plate as thick as the shaft. Most spheres are far from
// a tool, so the test is on squared distances inside a bounding box and the square root
// waits for a contact.
// Also the first instant a moving tool touches a centre (continuous collision), with which
// the tools' proxy moves without passing through the bowel.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/geometry.h"

namespace enteron::collision {

// A retractor's blade (ent_tool_desc blade_width_m, blade_length_m); a zero side: none.
struct Blade {
    Vec3 side = Vec3::Zero();  // half the blade's width, across the tool (local x, square to the axis), m
    double along = 0.0;        // the fraction of the shaft the blade covers from the tip, [0, 1]
};

// Where on the tool a centre is nearest: the shaft parameter s, the blade's w (0 on the
// shaft), and whether the nearest point slides with the centre along the axis (s inside its
// range) and across the blade (w inside (-1, 1)): the rigid tool's rates (shaft_contact.h).
struct ShaftPoint {
    double s = 0.0;
    double w = 0.0;
    bool slides_along = false;
    bool slides_across = false;
};

struct Shaft {
    Vec3 tip;
    Vec3 axis;             // tail - tip
    double inverse_axis2;  // 0 for a zero-length shaft (the tip alone)
    double reach;          // the tool's radius plus the bowel's
    Blade blade;
    double inverse_side2;  // 0 without a blade
    // A box around the tool, reach wide (and a hair more, for rounding): a centre outside
    // it cannot touch.
    Vec3 low, high;

    Shaft(const Vec3& tip_in, const Vec3& tail, double reach_in, const Blade& blade_in = {})
        : tip(tip_in), axis(tail - tip_in), reach(reach_in), blade(blade_in) {
        const double axis2 = axis.squaredNorm();
        inverse_axis2 = axis2 > 0.0 ? 1.0 / axis2 : 0.0;
        const double side2 = blade.side.squaredNorm();
        inverse_side2 = side2 > 0.0 ? 1.0 / side2 : 0.0;
        const double margin = reach * (1.0 + 1e-9);
        const Vec3 width = blade.side.cwiseAbs();
        low = tip.cwiseMin(tail).array() - margin - width.array();
        high = tip.cwiseMax(tail).array() + margin + width.array();
    }

    bool has_blade() const { return inverse_side2 > 0.0; }

    // For a centre p: where on the tool it is nearest, d = p minus that point, and |d|^2;
    // true if the sphere reaches into the tool (false, the rest unset, when p is outside
    // the box).
    bool touches(const Vec3& p, ShaftPoint* at, Vec3* d, double* distance2) const {
        if (!in_box(p)) return false;
        closest(p, at, d, distance2);
        return *distance2 < reach * reach;
    }

    // Whether p lies in the box around the tool (else it is farther than reach from it).
    bool in_box(const Vec3& p) const { return !((p.array() < low.array()) || (p.array() > high.array())).any(); }

    // The same without the box, for any centre: the nearer of the shaft's nearest point and
    // the blade's.
    void closest(const Vec3& p, ShaftPoint* at, Vec3* d, double* distance2) const {
        const Vec3 rel = p - tip;
        const double along = rel.dot(axis) * inverse_axis2;
        at->s = std::clamp(along, 0.0, 1.0);
        at->w = 0.0;
        at->slides_along = at->s > 0.0 && at->s < 1.0;
        at->slides_across = false;
        *d = rel - at->s * axis;
        *distance2 = d->squaredNorm();
        if (!has_blade()) return;
        const double s = std::clamp(along, 0.0, blade.along);
        const double w = std::clamp(rel.dot(blade.side) * inverse_side2, -1.0, 1.0);
        const Vec3 on_blade = rel - s * axis - w * blade.side;
        const double blade2 = on_blade.squaredNorm();
        if (!(blade2 < *distance2)) return;
        *at = {s, w, s > 0.0 && s < blade.along, w > -1.0 && w < 1.0};
        *d = on_blade;
        *distance2 = blade2;
    }

    // The tool moves by t * motion, t in [0, 1]: the first t at which the centre p comes
    // within `radius` of it (the centre moves by -t motion relative to the tool), or
    // infinity if it never does. A centre already within `radius` gives 0.
    double first_touch(const Vec3& p, const Vec3& motion, double radius) const {
        ShaftPoint at;
        double distance2;
        Vec3 d;
        closest(p, &at, &d, &distance2);
        if (distance2 <= radius * radius) return 0.0;
        double first = capsule_first_touch(tip, axis, inverse_axis2, p, motion, radius);
        if (!has_blade()) return first;
        // The rounded blade is convex: its first touch is the earliest of its four edges'
        // (capsules) and its two faces' (planes `radius` off the blade, within it).
        const Vec3 length = blade.along * axis;
        const Vec3 corners[4] = {tip - blade.side, tip + blade.side, tip + length + blade.side, tip + length - blade.side};
        for (int k = 0; k < 4; ++k) {
            const Vec3 edge = corners[(k + 1) % 4] - corners[k];
            const double edge2 = edge.squaredNorm();
            first = std::min(first, capsule_first_touch(corners[k], edge, edge2 > 0.0 ? 1.0 / edge2 : 0.0, p, motion,
                                                        radius));
        }
        const Vec3 normal = length.cross(blade.side);
        const double normal_norm = normal.norm();
        if (normal_norm > 0.0) {
            const Vec3 n = normal / normal_norm;
            const Vec3 origin = p - tip, ray = -motion;
            const double height = origin.dot(n), rate = ray.dot(n);
            const double face = height > 0.0 ? radius : -radius;
            if (std::fabs(height) > radius && rate != 0.0) {
                const double t = (face - height) / rate;
                const Vec3 hit = origin + t * ray;
                const double s = hit.dot(axis) * inverse_axis2, w = hit.dot(blade.side) * inverse_side2;
                if (t >= 0.0 && t <= 1.0 && s >= 0.0 && s <= blade.along && w >= -1.0 && w <= 1.0)
                    first = std::min(first, t);
            }
        }
        return first;
    }

private:
    // The first t in [0, 1] at which the centre p, moving by -t motion, comes within `radius`
    // of the segment from `start` along `segment` (inverse2 = 1 / |segment|^2, 0 for a
    // point), or infinity: its cylinder's side and its two end caps.
    static double capsule_first_touch(const Vec3& start, const Vec3& segment, double inverse2, const Vec3& p,
                                      const Vec3& motion, double radius) {
        const Vec3 origin = p - start;
        const Vec3 ray = -motion;
        const double radius2 = radius * radius;
        double first = std::numeric_limits<double>::infinity();
        // The side of the cylinder: |(o + t r) minus its part along the axis| = radius, the
        // point's axial coordinate within the segment.
        if (inverse2 > 0.0) {
            const Vec3 o_across = origin - (origin.dot(segment) * inverse2) * segment;
            const Vec3 r_across = ray - (ray.dot(segment) * inverse2) * segment;
            const double a = r_across.squaredNorm();
            const double b = o_across.dot(r_across);
            const double c = o_across.squaredNorm() - radius2;
            const double discriminant = b * b - a * c;
            if (a > 0.0 && discriminant >= 0.0) {
                const double t = (-b - std::sqrt(discriminant)) / a;
                const double along = (origin + t * ray).dot(segment) * inverse2;
                if (t >= 0.0 && t <= 1.0 && along >= 0.0 && along <= 1.0) first = t;
            }
        }
        // The two end caps: spheres of `radius` about the start and the end.
        for (const Vec3& centre : {Vec3::Zero().eval(), segment}) {
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
