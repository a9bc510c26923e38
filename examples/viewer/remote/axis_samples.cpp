// SPDX-License-Identifier: Apache-2.0
#include "axis_samples.h"

#include <algorithm>
#include <cmath>

namespace viewer {

void resample_evenly(const std::vector<double>& polyline_m, std::uint32_t count, std::vector<double>& out) {
    out.clear();
    const std::size_t n = polyline_m.size() / 3;
    if (n < 2 || count < 2) return;
    // The length from the first point to each point.
    std::vector<double> along(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
        const double* a = &polyline_m[3 * (i - 1)];
        const double* b = &polyline_m[3 * i];
        along[i] = along[i - 1] + std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                                            (b[2] - a[2]) * (b[2] - a[2]));
    }
    out.resize(3 * static_cast<std::size_t>(count));
    std::size_t segment = 1;  // the target lies between points segment - 1 and segment
    for (std::uint32_t k = 0; k < count; ++k) {
        const double target = along[n - 1] * k / (count - 1);
        while (segment < n - 1 && along[segment] < target) ++segment;
        const double span = along[segment] - along[segment - 1];
        const double f = span > 0.0 ? std::clamp((target - along[segment - 1]) / span, 0.0, 1.0) : 0.0;
        for (int c = 0; c < 3; ++c)
            out[3 * k + c] = (1.0 - f) * polyline_m[3 * (segment - 1) + c] + f * polyline_m[3 * segment + c];
    }
}

}  // namespace viewer
