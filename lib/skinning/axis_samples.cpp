#include "skinning/axis_samples.h"

#include <algorithm>
#include <cmath>

#include "skinning/frame_buffers.h"
#include "spline/catmull_rom.h"

namespace enteron::skinning {

template <typename ArcLengthOf>
void AxisSamples::sample(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                         ArcLengthOf arc_length_of) {
    Vec3 previous_tangent{1.0, 0.0, 0.0};
    for (std::size_t k = 0; k <= intervals_; ++k) {
        const double s = k == intervals_ ? double(count - 1) : table.parameter_at(arc_length_of(k));
        const Vec3 d = spline::evaluate(points_xyz, spline::weights_at(count, s, spline::Derivative::first));
        // A zero-speed stretch (coincident control points) keeps the last good tangent.
        const Vec3 t = normalized_or(d, previous_tangent);
        position_[phantoms_ + k] = spline::evaluate(points_xyz, spline::weights_at(count, s, spline::Derivative::value));
        tangent_[phantoms_ + k] = t;
        previous_tangent = t;
    }
}

void AxisSamples::build(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                        double spacing, double extension) {
    arc_.clear();
    length_ = table.total_length();
    intervals_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(length_ / spacing)));
    spacing_ = length_ / double(intervals_);
    phantoms_ = spacing_ > 0.0 && extension > 0.0 ? static_cast<std::size_t>(std::ceil(extension / spacing_)) : 0;
    const std::size_t total = intervals_ + 1 + 2 * phantoms_;
    resize_buffer(position_, total);
    resize_buffer(tangent_, total);

    sample(table, points_xyz, count, [&](std::size_t k) { return double(k) * spacing_; });
    const Vec3 first = position_[phantoms_], last = position_[phantoms_ + intervals_];
    const Vec3 t0 = tangent_[phantoms_], t1 = tangent_[phantoms_ + intervals_];
    for (std::size_t j = 1; j <= phantoms_; ++j) {
        position_[phantoms_ - j] = first - (double(j) * spacing_) * t0;
        tangent_[phantoms_ - j] = t0;
        position_[phantoms_ + intervals_ + j] = last + (double(j) * spacing_) * t1;
        tangent_[phantoms_ + intervals_ + j] = t1;
    }
}

void AxisSamples::build_at(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                           const std::vector<double>& arc_lengths) {
    length_ = table.total_length();
    intervals_ = arc_lengths.size() - 1;
    spacing_ = length_ / double(intervals_);
    phantoms_ = 0;
    resize_buffer(position_, arc_lengths.size());
    resize_buffer(tangent_, arc_lengths.size());
    resize_buffer(arc_, arc_lengths.size());
    std::copy(arc_lengths.begin(), arc_lengths.end(), arc_.begin());
    sample(table, points_xyz, count, [&](std::size_t k) { return arc_lengths[k]; });
}

}  // namespace enteron::skinning
