// SPDX-License-Identifier: Apache-2.0
// The library's geometry vocabulary: Eigen's fixed-size vectors for the
// per-contact and per-node maths, and maps that view our own packed x y z arrays (the
// state vectors, sphere centres) as 3-vectors without copying. One Vec3 for every layer.
//
// Private to the library: Eigen appears in no public header and no exported symbol.
// Two rules keep the bits of the hand-written loops this replaced (the library builds with
// -ffp-contract=off, so Eigen's expressions round like the loops did):
//  - a.dot(b) and a.squaredNorm() sum x, y, z in that order, like the loops (Eigen's SSE2
//    path, (x + y) + z; its scalar path would sum x + (y + z));
//  - a.normalized() divides each coordinate by the norm, where most of our laws multiply
//    by the inverse norm: write `d * (1.0 / length)` where the law says so.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>

namespace enteron {

using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;

inline constexpr double kPi = 3.14159265358979323846;

// a / |a| (as a times the inverse norm), or `fallback` for a vector too short to have a
// direction.
inline Vec3 normalized_or(const Vec3& a, const Vec3& fallback) {
    const double n = a.norm();
    return n > 1e-300 ? Vec3((1.0 / n) * a) : fallback;
}

// a a^T.
inline Mat3 outer(const Vec3& a) { return a * a.transpose(); }

// Point i of a packed x y z array, read-only or writable.
inline Eigen::Map<const Vec3> point_at(const double* xyz, std::size_t i) {
    return Eigen::Map<const Vec3>(xyz + 3 * i);
}
inline Eigen::Map<Vec3> point_at(double* xyz, std::size_t i) { return Eigen::Map<Vec3>(xyz + 3 * i); }

}  // namespace enteron
