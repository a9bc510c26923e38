#include "scene/shape_builder.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace enteron::scene {

namespace {

constexpr double kPi = 3.14159265358979323846;

double distance(const Vec3& a, const Vec3& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
}

// Walks along a curve given by its arc-length parametrisation and drops a point each time
// the straight distance from the previous point reaches `chord` (found by bisection
// between fine samples).
void place_by_chord(const std::function<Vec3(double)>& curve, double chord, std::size_t count,
                    double* out_xyz) {
    const double fine = chord / 64.0;
    Vec3 previous = curve(0.0);
    std::copy(previous.begin(), previous.end(), out_xyz);
    double s = 0.0;
    for (std::size_t i = 1; i < count; ++i) {
        double lo = s, hi = s;
        while (distance(curve(hi), previous) < chord) {
            lo = hi;
            hi += fine;
        }
        for (int iteration = 0; iteration < 60; ++iteration) {
            const double mid = 0.5 * (lo + hi);
            (distance(curve(mid), previous) < chord ? lo : hi) = mid;
        }
        s = hi;
        previous = curve(s);
        std::copy(previous.begin(), previous.end(), out_xyz + 3 * i);
    }
}

Vec3 helix_point(const ShapeConfig& shape, double s) {
    // Arc length per radian: sqrt(r^2 + (pitch / 2 pi)^2).
    const double rise = shape.helix_pitch / (2.0 * kPi);
    const double theta = s / std::sqrt(shape.helix_radius * shape.helix_radius + rise * rise);
    return {shape.center[0] + shape.helix_radius * std::cos(theta),
            shape.center[1] + shape.helix_radius * std::sin(theta), shape.center[2] + rise * theta};
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
    if (local <= leg) return {forward ? local : leg - local, y0, 0.0};
    const double angle = (local - leg) / turn_radius;  // 0 .. pi around the turn
    const double x = forward ? leg + turn_radius * std::sin(angle) : -turn_radius * std::sin(angle);
    return {x, y0 + turn_radius * (1.0 - std::cos(angle)), 0.0};
}

void centre_on(const Vec3& center, std::size_t count, double* xyz) {
    for (int c = 0; c < 3; ++c) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (std::size_t i = 0; i < count; ++i) {
            lo = std::min(lo, xyz[3 * i + c]);
            hi = std::max(hi, xyz[3 * i + c]);
        }
        const double shift = center[c] - 0.5 * (lo + hi);
        for (std::size_t i = 0; i < count; ++i) xyz[3 * i + c] += shift;
    }
}

}  // namespace

void build_shape(const ShapeConfig& shape, double length, std::size_t count, double* out_xyz) {
    const double chord = length / static_cast<double>(count - 1);
    switch (shape.kind) {
        case ShapeKind::line: {
            const Vec3& d = shape.direction;
            const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (std::size_t i = 0; i < count; ++i)
                for (int c = 0; c < 3; ++c)
                    out_xyz[3 * i + c] = shape.center[c] + d[c] / norm * chord * static_cast<double>(i);
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
