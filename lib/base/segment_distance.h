// SPDX-License-Identifier: Apache-2.0
// The closest points of two segments, P(s) = p0 + s (p1 - p0) and Q(t) = q0 + t (q1 - q0),
// s and t in [0, 1] (Ericson, Real-Time Collision Detection, 2005, section 5.1.9): the
// minimum of |P(s) - Q(t)|^2, a convex quadratic in (s, t), found on the unconstrained
// line-line solution clamped to the square, the other parameter then re-solved and clamped.
// Degenerate segments (points) and parallel ones are handled by the same clamps.
#pragma once

#include <algorithm>

#include "base/geometry.h"

namespace enteron {

struct SegmentClosest {
    double s;                 // on the first segment, in [0, 1]
    double t;                 // on the second, in [0, 1]
    double distance_squared;  // |P(s) - Q(t)|^2, m^2
};

inline SegmentClosest closest_points_of_segments(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
    const Vec3 d1 = p1 - p0;  // the first segment's direction
    const Vec3 d2 = q1 - q0;  // the second's
    const Vec3 r = p0 - q0;
    const double a = d1.squaredNorm();
    const double e = d2.squaredNorm();
    const double f = d2.dot(r);
    constexpr double kPoint = 1e-30;  // m^2: a segment this short is a point
    double s = 0.0, t = 0.0;
    if (a <= kPoint && e <= kPoint) {
        // both points
    } else if (a <= kPoint) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (e <= kPoint) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2);
            const double denominator = a * e - b * b;  // >= 0; 0 when parallel
            s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    const Vec3 gap = (p0 + s * d1) - (q0 + t * d2);
    return {s, t, gap.squaredNorm()};
}

}  // namespace enteron
