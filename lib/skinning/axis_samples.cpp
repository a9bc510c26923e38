#include "skinning/axis_samples.h"

#include <algorithm>
#include <cmath>

#include "spline/catmull_rom.h"

namespace enteron::skinning {

void AxisSamples::build(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                        double spacing, double extension) {
    length_ = table.total_length();
    intervals_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(length_ / spacing)));
    spacing_ = length_ / double(intervals_);
    phantoms_ = spacing_ > 0.0 && extension > 0.0 ? static_cast<std::size_t>(std::ceil(extension / spacing_)) : 0;
    const std::size_t total = intervals_ + 1 + 2 * phantoms_;
    position_.resize(total);
    tangent_.resize(total);

    Vec3 previous_tangent{1.0, 0.0, 0.0};
    for (std::size_t k = 0; k <= intervals_; ++k) {
        const double s = k == intervals_ ? double(count - 1) : table.parameter_at(double(k) * spacing_);
        double p[3], d[3];
        spline::evaluate(points_xyz, spline::weights_at(count, s, spline::Derivative::value), p);
        spline::evaluate(points_xyz, spline::weights_at(count, s, spline::Derivative::first), d);
        // A zero-speed stretch (coincident control points) keeps the last good tangent.
        const Vec3 t = normalized(load(d), previous_tangent);
        position_[phantoms_ + k] = load(p);
        tangent_[phantoms_ + k] = t;
        previous_tangent = t;
    }
    const Vec3 first = position_[phantoms_], last = position_[phantoms_ + intervals_];
    const Vec3 t0 = tangent_[phantoms_], t1 = tangent_[phantoms_ + intervals_];
    for (std::size_t j = 1; j <= phantoms_; ++j) {
        position_[phantoms_ - j] = first - (double(j) * spacing_) * t0;
        tangent_[phantoms_ - j] = t0;
        position_[phantoms_ + intervals_ + j] = last + (double(j) * spacing_) * t1;
        tangent_[phantoms_ + intervals_ + j] = t1;
    }
}

}  // namespace enteron::skinning
