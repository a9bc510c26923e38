// SPDX-License-Identifier: Apache-2.0
// The iso-value of a skin's field, calibrated for the bend of the axis.
//
// Both implicit skins sum a kernel over the axis within an arc-length window [-D, D] of
// the surface point's own axis point, and take the surface where that sum equals an
// iso-value. Calibrated on a straight axis, that iso-value puts the surface at exactly R
// there; on a bend it does not. Take the axis locally as an arc of curvature k (radius
// rho = 1 / k) and a point P at distance r from the axis point, at angle phi from the
// direction away from the centre of curvature, c = cos(phi). The arc point at arc length s
// is then at squared distance
//   |P - C(s)|^2 = r^2 + 4 rho (rho + r c) sin^2(s / (2 rho))
//               ~ r^2 + (1 + k r c) s^2 - (1 + k r c) k^2 s^4 / 12 + ...
// from P: the window looks shorter by sqrt(1 + k r c) on the outer side (c > 0) and longer
// on the inner side. For the 1/r^3 kernel and D = R, to first order in k R,
// f(r) = 2 D / (r^2 sqrt(r^2 + (1 + k r c) D^2)): the field at distance R is 13 % below the
// straight calibration on the outer side and 24 % above it on the inner side of a bend of
// radius 1.5 R, which moves the surface by -5 % and +8 % of R (measured). The error grows
// like k R, so it is below 1 % only where the axis bends with a radius above about 8 R.
//
// The cure is to compare the field with what the same window gives at distance R around
// an arc of the same curvature, F_arc(R; k, c) instead of F_arc(R; 0, 0); the skins multiply
// their field by
//   scale(k R, c) = F_arc(R; 0, 0) / F_arc(R; k, c)
// and keep the straight iso-value. This class tabulates the scale once (for each skin's
// own kernel, window and skeleton spacing) over k R in [0, 1] and c in [-1, 1], and
// interpolates bilinearly. On an arc the surface is then at R exactly, whatever the
// curvature; elsewhere the local arc is the osculating circle, and the field's dependence
// on the change of curvature along the window cancels to first order (it is odd in s).
// Only the scale's values on the surface itself matter (off it the scaled field just has
// to stay smooth and on the same side of the iso-value), so a skin may pass any c that is
// right at distance R: c r / R, which needs no square root, does. Tighter than R (k R > 1) a
// tube of radius R folds over itself on the inner side; there the scale of k R = 1 applies.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "base/geometry.h"

namespace enteron::skinning {

class BendCalibration {
public:
    static constexpr std::size_t kCurvatureIntervals = 32;  // k R from 0 to 1
    static constexpr std::size_t kCosineIntervals = 32;     // c from -1 to 1

    // Tabulates scale(k R, c) from field(k, c): the skin's windowed field at distance R
    // (the radius, m) in direction c from an axis point on an arc of curvature k (1/m), the
    // arc of arc_point() and the point of point_off_arc().
    template <typename Field>
    void build(double radius, Field field) {
        radius_ = radius;
        table_.resize((kCurvatureIntervals + 1) * (kCosineIntervals + 1));
        const double straight = field(0.0, 0.0);
        for (std::size_t i = 0; i <= kCurvatureIntervals; ++i)
            for (std::size_t j = 0; j <= kCosineIntervals; ++j) {
                const double k = double(i) / double(kCurvatureIntervals) / radius;
                const double c = -1.0 + 2.0 * double(j) / double(kCosineIntervals);
                table_[i * (kCosineIntervals + 1) + j] = straight / field(k, c);
            }
    }

    // The interpolation in curvature, done once per axis point and used for every c there.
    struct Row {
        const double* low = nullptr;  // the table's row below the curvature
        double fraction = 0.0;        // of the way to the next row
    };
    Row row(double curvature) const {
        const double x = std::clamp(curvature * radius_, 0.0, 1.0) * double(kCurvatureIntervals);
        const std::size_t i = std::min(std::size_t(x), kCurvatureIntervals - 1);
        return {&table_[i * (kCosineIntervals + 1)], x - double(i)};
    }

    // The scale for direction cosine c (clamped to [-1, 1]) on a row, and its derivative in
    // c (0 where clamped).
    static double scale(const Row& row, double c, double* d_scale_dc) {
        const double y = (std::clamp(c, -1.0, 1.0) + 1.0) * (0.5 * double(kCosineIntervals));
        const std::size_t j = std::min(std::size_t(y), kCosineIntervals - 1);
        const double* low = row.low + j;
        const double* high = low + (kCosineIntervals + 1);
        const double at_j = low[0] + row.fraction * (high[0] - low[0]);
        const double at_next = low[1] + row.fraction * (high[1] - low[1]);
        *d_scale_dc = std::fabs(c) < 1.0 ? (at_next - at_j) * (0.5 * double(kCosineIntervals)) : 0.0;
        return at_j + (y - double(j)) * (at_next - at_j);
    }
    double scale(double curvature, double c) const {
        double unused = 0.0;
        return scale(row(curvature), c, &unused);
    }

    // The arc of curvature k through the origin with tangent +x, bending towards +y (its
    // centre at (0, 1 / k, 0)), at arc length s; and the point at distance r from the origin
    // in the normal plane, in direction c (cos of the angle from -y, away from the centre).
    static Vec3 arc_point(double curvature, double s) {
        const double angle = curvature * s;
        if (std::fabs(angle) < 1e-6) return {s, 0.5 * curvature * s * s, 0.0};
        return {std::sin(angle) / curvature, (1.0 - std::cos(angle)) / curvature, 0.0};
    }
    static Vec3 point_off_arc(double r, double c) {
        return r * Vec3{0.0, -c, std::sqrt(std::max(0.0, 1.0 - c * c))};
    }

private:
    double radius_ = 1.0;
    std::vector<double> table_;
};

}  // namespace enteron::skinning
