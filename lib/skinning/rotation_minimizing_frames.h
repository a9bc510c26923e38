// SPDX-License-Identifier: Apache-2.0
// Rotation-minimising frames along sampled axis points, by the double reflection method of
// Wang, Juettler, Zheng and Liu (ACM TOG 2008). Rings placed on these frames do not twist
// around the axis (a Frenet frame would flip at inflections and spin on straight parts),
// so texture coordinates and the ring-to-ring quads stay regular.
#pragma once

#include <cstddef>
#include <vector>

#include "base/geometry.h"

namespace enteron::skinning {

class RotationMinimizingFrames {
public:
    // Frames for `count` samples (positions x, unit tangents t). The first normal is the
    // previous call's first normal made perpendicular to the new first tangent, so the
    // frames do not jump from one frame of the animation to the next.
    void build(const Vec3* x, const Vec3* t, std::size_t count);

    const Vec3& normal(std::size_t i) const { return normal_[i]; }      // r_i, unit, perpendicular to t_i
    const Vec3& binormal(std::size_t i) const { return binormal_[i]; }  // s_i = t_i x r_i

private:
    std::vector<Vec3> normal_;
    std::vector<Vec3> binormal_;
    Vec3 first_normal_{0.0, 0.0, 0.0};
};

// Any unit vector perpendicular to the unit vector t: t crossed with the first coordinate
// axis that is not nearly parallel to it (|component| < 0.6). The skins' one rule for a
// direction around an axis where nothing else gives one (a frame's first normal on a new
// axis; a point on the axis line itself).
Vec3 any_perpendicular(const Vec3& t);

// The angle of direction d around the axis in the frame (normal, binormal), in turns:
// atan2(d.binormal, d.normal) / (2 pi), in [0, 1). Within 2e-6 turn (a polynomial for atan,
// several times cheaper than std::atan2: the point skeleton takes one per vertex).
double turns_around(const Vec3& d, const Vec3& normal, const Vec3& binormal);

}  // namespace enteron::skinning
