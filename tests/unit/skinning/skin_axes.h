// SPDX-License-Identifier: Apache-2.0
// Exact axes for the skinning tests: control points of a straight line, a tight U-turn and
// a coil. The spline passes through its control points, so these are the axes themselves
// (up to the spline's small deviation between points on the curved parts).
#pragma once

#include <cmath>
#include <vector>

namespace skin_test {

constexpr double kPi = 3.14159265358979323846;

// n points along +x from the origin, `spacing` apart.
inline std::vector<double> straight_axis(int n, double spacing) {
    std::vector<double> q;
    for (int i = 0; i < n; ++i) q.insert(q.end(), {i * spacing, 0.0, 0.0});
    return q;
}

// Two legs along -x, `gap` apart (axis to axis), joined by a half circle of diameter gap
// around the origin; points about `spacing` apart along the path.
inline std::vector<double> u_turn_axis(double leg, double gap, double spacing) {
    std::vector<double> q;
    const double r = 0.5 * gap;
    const int leg_points = int(std::ceil(leg / spacing));
    for (int i = 0; i < leg_points; ++i) q.insert(q.end(), {-leg + i * (leg / leg_points), -r, 0.0});
    const int arc_points = int(std::ceil(kPi * r / spacing));
    for (int i = 0; i < arc_points; ++i) {
        const double a = -0.5 * kPi + kPi * i / arc_points;
        q.insert(q.end(), {r * std::cos(a), r * std::sin(a), 0.0});
    }
    for (int i = 0; i <= leg_points; ++i) q.insert(q.end(), {-i * (leg / leg_points), r, 0.0});
    return q;
}

// The U-turn of u_turn_axis with the middle of its second leg (at x = -leg / 2) pushed
// towards the first by `press` times a smooth bump cos^2(pi (x + leg / 2) / (2 half)) over
// |x + leg / 2| < half: the legs `gap - press` apart at the bump's top, `gap` elsewhere.
inline std::vector<double> pressed_u_turn_axis(double leg, double gap, double press, double half, double spacing) {
    std::vector<double> q = u_turn_axis(leg, gap, spacing);
    for (std::size_t i = 0; i < q.size(); i += 3) {
        const double x = q[i] + 0.5 * leg;
        if (q[i + 1] > 0.0 && std::fabs(x) < half && q[i] < -0.5 * gap) {
            const double c = std::cos(0.5 * kPi * x / half);
            q[i + 1] -= press * c * c;
        }
    }
    return q;
}

// A coil: helix of radius `radius`, rise `pitch` per turn, `turns` turns, points about
// `spacing` apart.
inline std::vector<double> coil_axis(double radius, double pitch, double turns, double spacing) {
    std::vector<double> q;
    const double per_turn = std::sqrt(std::pow(2 * kPi * radius, 2) + pitch * pitch);
    const int n = int(std::ceil(turns * per_turn / spacing)) + 1;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * kPi * turns * i / (n - 1);
        q.insert(q.end(), {radius * std::cos(a), radius * std::sin(a), pitch * a / (2 * kPi)});
    }
    return q;
}

}  // namespace skin_test
