// SPDX-License-Identifier: Apache-2.0
#include "axis_tube.h"

#include <Eigen/Geometry>

#include <cmath>

namespace viewer {

namespace {

Eigen::Vector3d axis_tube_point(const std::vector<double>& axis_m, std::size_t i) {
    return Eigen::Vector3d(axis_m[3 * i], axis_m[3 * i + 1], axis_m[3 * i + 2]);
}

// Any unit vector perpendicular to t (t unit).
Eigen::Vector3d perpendicular(const Eigen::Vector3d& t) {
    const Eigen::Vector3d other = std::abs(t.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return t.cross(other).normalized();
}

}  // namespace

void make_axis_tube(const std::vector<double>& axis_m, double radius_m, int sides, MeshArrays& out) {
    out.positions_m.clear();
    out.normals.clear();
    out.axis_u.clear();
    out.indices.clear();
    const std::size_t points = axis_m.size() / 3;
    if (points < 2 || sides < 3) return;
    auto add_vertex = [&out](const Eigen::Vector3d& p, const Eigen::Vector3d& n, double u) {
        for (int c = 0; c < 3; ++c) {
            out.positions_m.push_back(static_cast<float>(p[c]));
            out.normals.push_back(static_cast<float>(n[c]));
        }
        out.axis_u.push_back(static_cast<float>(u));
    };
    // The tangent at a point: the central difference (one-sided at the ends).
    auto tangent = [&](std::size_t i) {
        const Eigen::Vector3d d = axis_tube_point(axis_m, i + 1 < points ? i + 1 : i) - axis_tube_point(axis_m, i > 0 ? i - 1 : i);
        return d.norm() > 0.0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitX();
    };
    Eigen::Vector3d t = tangent(0);
    Eigen::Vector3d normal = perpendicular(t);
    for (std::size_t i = 0; i < points; ++i) {
        const Eigen::Vector3d next_t = tangent(i);
        // Parallel transport: turn the frame by the rotation that takes t to next_t.
        normal = Eigen::Quaterniond::FromTwoVectors(t, next_t) * normal;
        normal = (normal - normal.dot(next_t) * next_t).normalized();
        if (!normal.allFinite()) normal = perpendicular(next_t);
        t = next_t;
        const Eigen::Vector3d binormal = t.cross(normal);
        const double u = static_cast<double>(i) / static_cast<double>(points - 1);  // evenly in arc length
        for (int k = 0; k < sides; ++k) {
            const double angle = 2.0 * EIGEN_PI * k / sides;
            const Eigen::Vector3d n = std::cos(angle) * normal + std::sin(angle) * binormal;
            add_vertex(axis_tube_point(axis_m, i) + radius_m * n, n, u);
        }
    }
    const auto side = static_cast<std::uint32_t>(sides);
    for (std::uint32_t i = 0; i + 1 < points; ++i)
        for (std::uint32_t k = 0; k < side; ++k) {
            const std::uint32_t a = i * side + k, b = i * side + (k + 1) % side;
            const std::uint32_t c = a + side, d = b + side;
            // (normal, binormal, t) is right-handed: a, b, d turns counter-clockwise seen from outside.
            out.indices.insert(out.indices.end(), {a, b, d, a, d, c});
        }
    // The caps: a fan around each end's centre, facing out along -t and +t.
    for (int end = 0; end < 2; ++end) {
        const std::size_t i = end == 0 ? 0 : points - 1;
        const Eigen::Vector3d n = end == 0 ? Eigen::Vector3d(-tangent(0)) : tangent(points - 1);
        const auto centre = static_cast<std::uint32_t>(out.axis_u.size());
        add_vertex(axis_tube_point(axis_m, i), n, end == 0 ? 0.0 : 1.0);
        const auto ring = static_cast<std::uint32_t>(i) * side;
        for (std::uint32_t k = 0; k < side; ++k) {
            const std::uint32_t a = ring + k, b = ring + (k + 1) % side;
            if (end == 0)
                out.indices.insert(out.indices.end(), {centre, b, a});
            else
                out.indices.insert(out.indices.end(), {centre, a, b});
        }
    }
}

}  // namespace viewer
