// SPDX-License-Identifier: Apache-2.0
#include "spline/arc_length.h"

#include <algorithm>
#include <cmath>

#include "numerics/gauss_legendre.h"
#include "spline/catmull_rom.h"

namespace enteron::spline {

namespace {

constexpr std::size_t kSubdivisions = 8;  // intervals per segment

double speed_at(const double* points, std::size_t count, Ends ends, double s) {
    return evaluate(points, weights_at(count, s, Derivative::first, ends)).norm();
}

double integrate_between(const double* points, std::size_t count, Ends ends, double s0, double s1) {
    // Within one interval the speed is smooth: 5-point Gauss is accurate to ~1e-12.
    constexpr auto rule = numerics::gauss_legendre<5>();
    double sum = 0.0;
    for (const auto& node : rule) sum += node.weight * speed_at(points, count, ends, s0 + (s1 - s0) * node.t);
    return sum * (s1 - s0);
}

// The parameter in [s_lo, s_hi] at arc length `target`, where the interval starts at
// arc length `start` and is `span` long: interpolation, then Newton's method.
double invert_in_interval(const double* points, std::size_t count, Ends ends, double s_lo, double s_hi,
                          double start, double span, double target, double total) {
    double s = span > 0.0 ? s_lo + (target - start) / span * (s_hi - s_lo) : s_lo;
    for (int iteration = 0; iteration < 4; ++iteration) {
        const double error = start + integrate_between(points, count, ends, s_lo, s) - target;
        const double v = speed_at(points, count, ends, s);
        if (!(v > 0.0)) break;  // a degenerate (zero-speed) stretch: keep the interpolated guess
        s = std::clamp(s - error / v, s_lo, s_hi);
        if (std::fabs(error) < 1e-14 * (1.0 + total)) break;
    }
    return s;
}

double interval_end(std::size_t k, std::size_t count) {
    return std::min(double(k + 1) / kSubdivisions, double(count - 1));
}

}  // namespace

double ArcLengthTable::speed(double s) const { return speed_at(points_, count_, ends_, s); }

double ArcLengthTable::integrate(double s0, double s1) const {
    return integrate_between(points_, count_, ends_, s0, s1);
}

SegmentStretch largest_segment_stretch(const double* points_xyz, std::size_t count, double rest_segment_length,
                                       Ends ends) {
    double total = 0.0, largest = 0.0, largest_start = 0.0, largest_length = 0.0;
    bool found = false;
    for (std::size_t segment = 0; segment + 1 < count; ++segment) {
        double length = 0.0;
        for (std::size_t k = 0; k < kSubdivisions; ++k)
            length += integrate_between(points_xyz, count, ends, segment + double(k) / kSubdivisions,
                                        segment + double(k + 1) / kSubdivisions);
        if (!found || length > largest) {
            found = true;
            largest = length;
            largest_start = total;
            largest_length = length;
        }
        total += length;
    }
    SegmentStretch out;
    out.stretch = largest / rest_segment_length - 1.0;
    out.u = total > 0.0 ? (largest_start + 0.5 * largest_length) / total : 0.0;
    return out;
}

void sample_evenly(const double* points_xyz, std::size_t count, std::size_t samples, double* out_xyz, Ends ends) {
    const std::size_t intervals = (count - 1) * kSubdivisions;
    double total = 0.0;
    for (std::size_t k = 0; k < intervals; ++k)
        total += integrate_between(points_xyz, count, ends, double(k) / kSubdivisions, interval_end(k, count));
    point_at(out_xyz, 0) = evaluate(points_xyz, weights_at(count, 0.0, Derivative::value, ends));
    std::size_t next = 1;
    double start = 0.0;
    for (std::size_t k = 0; k < intervals && next + 1 < samples; ++k) {
        const double s_lo = double(k) / kSubdivisions, s_hi = interval_end(k, count);
        const double span = integrate_between(points_xyz, count, ends, s_lo, s_hi);
        for (; next + 1 < samples; ++next) {
            const double target = total * double(next) / double(samples - 1);
            if (target > start + span) break;
            const double s = invert_in_interval(points_xyz, count, ends, s_lo, s_hi, start, span, target, total);
            point_at(out_xyz, next) = evaluate(points_xyz, weights_at(count, s, Derivative::value, ends));
        }
        start += span;
    }
    // Round-off may leave samples just short of the end; the last is the end point itself.
    for (; next < samples; ++next)
        point_at(out_xyz, next) = evaluate(points_xyz, weights_at(count, double(count - 1), Derivative::value, ends));
}

void ArcLengthTable::build(const double* points_xyz, std::size_t count, Ends ends) {
    points_ = points_xyz;
    count_ = count;
    ends_ = ends;
    const std::size_t entries = (count - 1) * kSubdivisions + 1;
    cumulative_.resize(entries);
    cumulative_[0] = 0.0;
    for (std::size_t k = 1; k < entries; ++k)
        cumulative_[k] = cumulative_[k - 1] + integrate(double(k - 1) / kSubdivisions, interval_end(k - 1, count));
}

double ArcLengthTable::length_at(double s) const {
    s = std::clamp(s, 0.0, double(count_ - 1));
    const std::size_t k = std::min(static_cast<std::size_t>(s * kSubdivisions), cumulative_.size() - 1);
    const double s0 = double(k) / kSubdivisions;
    return cumulative_[k] + (s > s0 ? integrate(s0, s) : 0.0);
}

double ArcLengthTable::parameter_at(double length) const {
    const double total = total_length();
    if (!(length > 0.0)) return 0.0;
    if (length >= total) return double(count_ - 1);
    // The table interval that holds `length`, then Newton's method inside it.
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), length);
    const std::size_t k = static_cast<std::size_t>(it - cumulative_.begin()) - 1;
    return invert_in_interval(points_, count_, ends_, double(k) / kSubdivisions, interval_end(k, count_), cumulative_[k],
                              cumulative_[k + 1] - cumulative_[k], length, total);
}

void ArcLengthTable::sample_evenly(std::size_t samples, double* out_xyz) const {
    const double total = total_length();
    for (std::size_t i = 0; i < samples; ++i) {
        const double target = total * double(i) / double(samples - 1);
        const double s = i + 1 == samples ? double(count_ - 1) : parameter_at(target);
        point_at(out_xyz, i) = evaluate(points_, weights_at(count_, s, Derivative::value, ends_));
    }
}

}  // namespace enteron::spline
