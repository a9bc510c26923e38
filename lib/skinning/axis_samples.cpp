// SPDX-License-Identifier: Apache-2.0
#include "skinning/axis_samples.h"

#include <algorithm>
#include <cmath>

#include "skinning/bend_calibration.h"
#include "skinning/frame_buffers.h"
#include "spline/catmull_rom.h"

namespace enteron::skinning {

template <typename ArcLengthOf>
void AxisSamples::sample(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                         ArcLengthOf arc_length_of, Curvature curvature) {
    resize_buffer(curvature_, curvature == Curvature::compute ? position_.size() : 0);
    resize_buffer(parameter_, position_.size());
    Vec3 previous_tangent{1.0, 0.0, 0.0};
    for (std::size_t k = 0; k <= intervals_; ++k) {
        const double s = k == intervals_ ? double(count - 1) : table.parameter_at(arc_length_of(k));
        const Vec3 d = spline::evaluate(points_xyz, spline::weights_at(count, s, spline::Derivative::first));
        // A zero-speed stretch (coincident control points) keeps the last good tangent.
        const Vec3 t = normalized_or(d, previous_tangent);
        position_[phantoms_ + k] = spline::evaluate(points_xyz, spline::weights_at(count, s, spline::Derivative::value));
        tangent_[phantoms_ + k] = t;
        parameter_[phantoms_ + k] = s;
        previous_tangent = t;
        if (curvature == Curvature::compute) curvature_[phantoms_ + k] = curvature_vector(points_xyz, count, s, d, t);
    }
}

Vec3 AxisSamples::curvature_vector(const double* points_xyz, std::size_t count, double s, const Vec3& d,
                                   const Vec3& t) {
    // dt/ds = (P'' - (P''.t) t) / |P'|^2, P' and P'' the derivatives in the spline parameter.
    // In the end segments P'' swings from minus to twice the bend of their neighbours (the
    // end condition's linear extrapolation, catmull_rom.h): there a window sees the bend of
    // the inner knot, taken instead.
    const double inner = std::clamp(s, 1.0, std::max(1.0, double(count) - 2.0));
    const Vec3 dd = spline::evaluate(points_xyz, spline::weights_at(count, inner, spline::Derivative::second));
    const double speed2 = d.squaredNorm();
    return speed2 > 0.0 ? Vec3((1.0 / speed2) * (dd - dd.dot(t) * t)) : Vec3::Zero();
}

Vec3 AxisSamples::tangent_at(double s) const {
    const std::size_t last = position_.size() - 1;
    std::size_t i = 0;
    if (arc_.empty()) {
        i = std::size_t(std::clamp(std::floor(s / spacing_ + double(phantoms_)), 0.0, double(last - 1)));
    } else {
        i = std::size_t(std::upper_bound(arc_.begin(), arc_.end(), s) - arc_.begin());
        i = std::clamp<std::size_t>(i, 1, last) - 1;
    }
    const double span = arc_length(i + 1) - arc_length(i);
    const double w = span > 0.0 ? std::clamp((s - arc_length(i)) / span, 0.0, 1.0) : 0.0;
    return normalized_or((1.0 - w) * tangent_[i] + w * tangent_[i + 1], tangent_[i]);
}

Vec3 AxisSamples::mean_bend(double s, double half) const {
    const Vec3 turn = tangent_at(s + half) - tangent_at(s - half);
    const double chord = turn.norm();
    if (!(chord > 0.0) || !(half > 0.0)) return Vec3::Zero();
    const double angle = 2.0 * std::asin(std::min(1.0, 0.5 * chord));
    return (angle / (2.0 * half * chord)) * turn;
}

std::size_t AxisSamples::intervals_for(double length, double spacing) {
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(length / spacing)));
}

void AxisSamples::build(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                        std::size_t intervals, double extension, Curvature curvature) {
    arc_.clear();
    length_ = table.total_length();
    intervals_ = std::max<std::size_t>(1, intervals);
    spacing_ = length_ / double(intervals_);
    phantoms_ = spacing_ > 0.0 && extension > 0.0 ? static_cast<std::size_t>(std::ceil(extension / spacing_)) : 0;
    const std::size_t total = intervals_ + 1 + 2 * phantoms_;
    resize_buffer(position_, total);
    resize_buffer(tangent_, total);
    sample(table, points_xyz, count, [&](std::size_t k) { return double(k) * spacing_; }, curvature);
    extend_ends(points_xyz, count, spacing_, spacing_, curvature);
}

void AxisSamples::extend_ends(const double* points_xyz, std::size_t count, double first_spacing, double last_spacing,
                              Curvature curvature) {
    if (phantoms_ == 0) return;
    // The phantoms continue each end along its osculating circle (a straight line where it
    // does not bend), so that a window reaching past an end sees the same bend as one
    // inside (bend_calibration.h). The curvature is capped at a quarter turn over the
    // phantoms, so that a kink at an end cannot curl them back onto the axis.
    const auto extend = [&](std::size_t end, double parameter, double direction, double step) {
        const double reach = double(phantoms_) * step, largest = 0.5 * kPi / reach;
        const Vec3 t = tangent_[end];
        const Vec3 d = spline::evaluate(points_xyz, spline::weights_at(count, parameter, spline::Derivative::first));
        const Vec3 bend = curvature_vector(points_xyz, count, parameter, d, t);
        const double k = std::min(bend.norm(), largest);
        const Vec3 inward = normalized_or(bend, Vec3::Zero());
        for (std::size_t j = 1; j <= phantoms_; ++j) {
            const double s = direction * double(j) * step;
            const Vec3 arc = BendCalibration::arc_point(k, s);  // (along t, towards the centre, 0)
            const std::size_t i = direction > 0.0 ? end + j : end - j;
            position_[i] = position_[end] + arc.x() * t + arc.y() * inward;
            tangent_[i] = std::cos(k * s) * t + std::sin(k * s) * inward;
            parameter_[i] = parameter;
            if (curvature == Curvature::compute) curvature_[i] = k * inward;
            if (!arc_.empty()) arc_[i] = arc_[end] + s;
        }
    };
    extend(phantoms_, 0.0, -1.0, first_spacing);
    extend(phantoms_ + intervals_, double(count - 1), 1.0, last_spacing);
}

void AxisSamples::build_at(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                           const std::vector<double>& arc_lengths, Curvature curvature, double extension) {
    length_ = table.total_length();
    intervals_ = arc_lengths.size() - 1;
    spacing_ = length_ / double(intervals_);
    // Phantoms at each end's own spacing, as many as the finer end needs.
    const double first_spacing = arc_lengths[1] - arc_lengths[0];
    const double last_spacing = arc_lengths[intervals_] - arc_lengths[intervals_ - 1];
    const double finer = std::min(first_spacing, last_spacing);
    phantoms_ = finer > 0.0 && extension > 0.0 ? static_cast<std::size_t>(std::ceil(extension / finer)) : 0;
    const std::size_t total = arc_lengths.size() + 2 * phantoms_;
    resize_buffer(position_, total);
    resize_buffer(tangent_, total);
    resize_buffer(arc_, total);
    std::copy(arc_lengths.begin(), arc_lengths.end(), arc_.begin() + std::ptrdiff_t(phantoms_));
    sample(table, points_xyz, count, [&](std::size_t k) { return arc_lengths[k]; }, curvature);
    extend_ends(points_xyz, count, first_spacing, last_spacing, curvature);
}

}  // namespace enteron::skinning
