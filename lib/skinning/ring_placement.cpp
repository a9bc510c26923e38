// SPDX-License-Identifier: Apache-2.0
#include "skinning/ring_placement.h"

#include <algorithm>
#include <cmath>

#include "skinning/frame_buffers.h"

namespace enteron::skinning {

const std::vector<double>& RingPlacement::place(const AxisSamples& axis, double radius, double max_spacing,
                                                double min_spacing, double chord_error, std::size_t level_step) {
    const std::size_t first = axis.phantoms(), n = axis.intervals() + 1;
    const double h = axis.spacing(), length = axis.length();
    // Curvature at each real sample from its neighbours' tangents, 1/m.
    resize_buffer(curvature_, n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = first + (i > 0 ? i - 1 : 0), b = first + std::min(i + 1, n - 1);
        const double span = double(b - a) * h;
        curvature_[i] = span > 0.0 ? (axis.tangent(b) - axis.tangent(a)).norm() / span : 0.0;
    }
    // The largest curvature within max_spacing / 2, then the ring density 1 / Delta.
    const auto reach = std::size_t(std::ceil(0.5 * max_spacing / h));
    resize_buffer(density_, n);
    for (std::size_t i = 0; i < n; ++i) {
        double curvature = 0.0;
        for (std::size_t j = i - std::min(i, reach); j <= std::min(n - 1, i + reach); ++j)
            curvature = std::max(curvature, curvature_[j]);
        density_[i] = 1.0 / spacing_for(curvature, radius, chord_error, min_spacing, max_spacing);
    }
    // Rings at equal steps of the integral of the density (trapezoids between samples).
    double total = 0.0;
    for (std::size_t i = 0; i + 1 < n; ++i) total += 0.5 * (density_[i] + density_[i + 1]) * h;
    auto rings = std::max<std::size_t>(1, std::size_t(std::ceil(total - 1e-9)));
    if (level_step > 0) {
        const std::size_t level = level_step * ((rings + level_step - 1) / level_step);
        if (level > level_ || level + level_step < level_) level_ = level;
        rings = level_;
    }
    resize_buffer(arc_lengths_, rings + 1);
    arc_lengths_[0] = 0.0;
    double integral = 0.0;
    std::size_t i = 0;
    for (std::size_t m = 1; m < rings; ++m) {
        const double target = total * double(m) / double(rings);
        double step = 0.5 * (density_[i] + density_[i + 1]) * h;
        while (integral + step < target && i + 2 < n) {
            integral += step;
            ++i;
            step = 0.5 * (density_[i] + density_[i + 1]) * h;
        }
        // Inside sample interval i: the density is linear, solve for the fraction.
        const double d0 = density_[i], d1 = density_[i + 1], rest = (target - integral) / h;
        // (d1 - d0) / 2 w^2 + d0 w = rest, in the form without cancellation.
        const double w = 2.0 * rest / (d0 + std::sqrt(std::max(0.0, d0 * d0 + 2.0 * (d1 - d0) * rest)));
        arc_lengths_[m] = (double(i) + std::clamp(w, 0.0, 1.0)) * h;
    }
    arc_lengths_[rings] = length;
    return arc_lengths_;
}

}  // namespace enteron::skinning
