// SPDX-License-Identifier: Apache-2.0
#include "scene/shape_builder.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace enteron::scene {

namespace {

// Walks along a curve given by its arc-length parametrisation and drops a point each time
// the straight distance from the previous point reaches `chord` (found by bisection
// between fine samples).
void place_by_chord(const std::function<Vec3(double)>& curve, double chord, std::size_t count,
                    double* out_xyz) {
    const double fine = chord / 64.0;
    Vec3 previous = curve(0.0);
    point_at(out_xyz, 0) = previous;
    double s = 0.0;
    for (std::size_t i = 1; i < count; ++i) {
        double lo = s, hi = s;
        while ((curve(hi) - previous).norm() < chord) {
            lo = hi;
            hi += fine;
        }
        for (int iteration = 0; iteration < 60; ++iteration) {
            const double mid = 0.5 * (lo + hi);
            ((curve(mid) - previous).norm() < chord ? lo : hi) = mid;
        }
        s = hi;
        previous = curve(s);
        point_at(out_xyz, i) = previous;
    }
}

Vec3 helix_point(const ShapeConfig& shape, double s) {
    // Arc length per radian: sqrt(r^2 + (pitch / 2 pi)^2).
    const double rise = shape.helix_pitch / (2.0 * kPi);
    const double theta = s / std::sqrt(shape.helix_radius * shape.helix_radius + rise * rise);
    return shape.center + Vec3(shape.helix_radius * std::cos(theta), shape.helix_radius * std::sin(theta), rise * theta);
}

// Legs along x joined by half circles, stacked in +y from the origin; centred afterwards.
Vec3 serpentine_point(const ShapeConfig& shape, double s) {
    const double leg = shape.leg_length;
    const double turn_radius = 0.5 * shape.leg_spacing;
    const double turn = kPi * turn_radius;
    const double period = leg + turn;
    const double index = std::floor(s / period);
    const double local = s - index * period;
    const bool forward = static_cast<long long>(index) % 2 == 0;
    const double y0 = index * shape.leg_spacing;
    if (local <= leg) return Vec3(forward ? local : leg - local, y0, 0.0);
    const double angle = (local - leg) / turn_radius;  // 0 .. pi around the turn
    const double x = forward ? leg + turn_radius * std::sin(angle) : -turn_radius * std::sin(angle);
    return Vec3(x, y0 + turn_radius * (1.0 - std::cos(angle)), 0.0);
}

// Moves the points so that the middle of their bounding box is `center`.
void centre_on(const Vec3& center, std::size_t count, double* xyz) {
    Eigen::Map<Eigen::Matrix3Xd> points(xyz, 3, static_cast<Eigen::Index>(count));
    const Vec3 middle = 0.5 * (points.rowwise().minCoeff() + points.rowwise().maxCoeff());
    points.colwise() += center - middle;
}

}  // namespace

void build_shape(const ShapeConfig& shape, double length, std::size_t count, double* out_xyz) {
    const double chord = length / static_cast<double>(count - 1);
    switch (shape.kind) {
        case ShapeKind::line: {
            const Vec3 direction = shape.direction / shape.direction.norm();
            for (std::size_t i = 0; i < count; ++i)
                point_at(out_xyz, i) = shape.center + direction * chord * static_cast<double>(i);
            return;
        }
        case ShapeKind::helix:
            place_by_chord([&](double s) { return helix_point(shape, s); }, chord, count, out_xyz);
            return;
        case ShapeKind::serpentine:
            place_by_chord([&](double s) { return serpentine_point(shape, s); }, chord, count, out_xyz);
            centre_on(shape.center, count, out_xyz);
            return;
        case ShapeKind::points:
            std::copy(shape.points.begin(), shape.points.begin() + 3 * count, out_xyz);
            return;
    }
}

}  // namespace enteron::scene
