// SPDX-License-Identifier: Apache-2.0
#include "skinning/rotation_minimizing_frames.h"

#include <algorithm>
#include <cmath>

#include "skinning/frame_buffers.h"

namespace enteron::skinning {

Vec3 any_perpendicular(const Vec3& t) {
    const Vec3 axis = std::fabs(t.x()) < 0.6 ? Vec3{1, 0, 0} : (std::fabs(t.y()) < 0.6 ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
    return normalized_or(t.cross(axis), Vec3{0, 0, 1});
}

void RotationMinimizingFrames::build(const Vec3* x, const Vec3* t, std::size_t count) {
    resize_buffer(normal_, count);
    resize_buffer(binormal_, count);
    if (count == 0) return;
    // Temporal coherence of the whole frame field: start from last frame's first normal.
    Vec3 r = first_normal_ - first_normal_.dot(t[0]) * t[0];
    r = r.norm() > 1e-6 ? normalized_or(r, r) : any_perpendicular(t[0]);
    first_normal_ = r;
    normal_[0] = r;
    binormal_[0] = t[0].cross(r);
    for (std::size_t i = 0; i + 1 < count; ++i) {
        // Reflection 1 in the bisecting plane of x_i and x_{i+1}.
        const Vec3 v1 = x[i + 1] - x[i];
        const double c1 = v1.squaredNorm();
        Vec3 r_left = r, t_left = t[i];
        if (c1 > 0.0) {
            r_left = r - (2.0 / c1) * v1.dot(r) * v1;
            t_left = t[i] - (2.0 / c1) * v1.dot(t[i]) * v1;
        }
        // Reflection 2 maps the reflected tangent onto t_{i+1}.
        const Vec3 v2 = t[i + 1] - t_left;
        const double c2 = v2.squaredNorm();
        Vec3 next = c2 > 0.0 ? r_left - (2.0 / c2) * v2.dot(r_left) * v2 : r_left;
        // Remove round-off drift so the frame stays orthonormal over thousands of samples.
        next = next - next.dot(t[i + 1]) * t[i + 1];
        r = next.norm() > 1e-12 ? normalized_or(next, next) : any_perpendicular(t[i + 1]);
        normal_[i + 1] = r;
        binormal_[i + 1] = t[i + 1].cross(r);
    }
}

double turns_around(const Vec3& d, const Vec3& normal, const Vec3& binormal) {
    const double x = d.dot(normal), y = d.dot(binormal);
    const double ax = std::fabs(x), ay = std::fabs(y);
    const double big = std::max(ax, ay);
    if (!(big > 0.0)) return 0.0;
    // atan(a) on [0, 1], a = min / max, by the polynomial of Abramowitz and Stegun 4.4.47
    // (within 1e-5 rad), then the octant.
    const double a = std::min(ax, ay) / big, a2 = a * a;
    double angle = a * (0.9998660 + a2 * (-0.3302995 + a2 * (0.1801410 + a2 * (-0.0851330 + a2 * 0.0208351))));
    if (ay > ax) angle = 0.5 * kPi - angle;
    if (x < 0.0) angle = kPi - angle;
    double turns = angle * (0.5 / kPi);
    if (y < 0.0) turns = 1.0 - turns;
    return turns < 1.0 ? turns : 0.0;
}

}  // namespace enteron::skinning
