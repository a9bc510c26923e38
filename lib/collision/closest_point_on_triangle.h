// SPDX-License-Identifier: Apache-2.0
// The point of a triangle closest to a point, and which feature of the triangle it lies on
// (a corner, an edge or the inside): Ericson, Real-Time Collision Detection (2005), 5.1.5,
// which tests the Voronoi regions of the corners, then of the edges, then takes the
// barycentric projection. The feature picks the pseudo-normal that signs the distance
// (mesh_topology.h).
#pragma once

#include <cstdint>

#include "base/geometry.h"

namespace enteron::collision {

// Where on the triangle (a, b, c) the closest point lies.
enum class TriangleFeature : uint8_t { corner_a, corner_b, corner_c, edge_ab, edge_bc, edge_ca, face };

struct TrianglePoint {
    Vec3 point;
    TriangleFeature feature;
};

inline TrianglePoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return {a, TriangleFeature::corner_a};
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return {b, TriangleFeature::corner_b};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {a + (d1 / (d1 - d3)) * ab, TriangleFeature::edge_ab};
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return {c, TriangleFeature::corner_c};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {a + (d2 / (d2 - d6)) * ac, TriangleFeature::edge_ca};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
        return {b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b), TriangleFeature::edge_bc};
    const double denominator = 1.0 / (va + vb + vc);
    return {a + (vb * denominator) * ab + (vc * denominator) * ac, TriangleFeature::face};
}

}  // namespace enteron::collision
