#include "spline/catmull_rom.h"

#include <algorithm>
#include <cmath>

namespace enteron::spline {

std::array<double, 4> raw_weights(double t, Derivative order) {
    const double t2 = t * t;
    const double t3 = t2 * t;
    switch (order) {
        case Derivative::value:
            return {0.5 * (-t3 + 2 * t2 - t), 0.5 * (3 * t3 - 5 * t2 + 2),
                    0.5 * (-3 * t3 + 4 * t2 + t), 0.5 * (t3 - t2)};
        case Derivative::first:
            return {0.5 * (-3 * t2 + 4 * t - 1), 0.5 * (9 * t2 - 10 * t),
                    0.5 * (-9 * t2 + 8 * t + 1), 0.5 * (3 * t2 - 2 * t)};
        case Derivative::second:
        default:
            return {0.5 * (-6 * t + 4), 0.5 * (18 * t - 10), 0.5 * (-18 * t + 8), 0.5 * (6 * t - 2)};
    }
}

SegmentWeights segment_weights(std::size_t count, std::size_t segment, double t, Derivative order) {
    const std::array<double, 4> r = raw_weights(t, order);
    SegmentWeights out;
    // With count >= 4 the first and the last segment are never the same one.
    if (segment == 0) {
        // q_{-1} = 2 q_0 - q_1 ; the window is q_0 .. q_3.
        out.first = 0;
        out.w = {r[1] + 2 * r[0], r[2] - r[0], r[3], 0.0};
    } else if (segment + 2 == count) {
        // q_n = 2 q_{n-1} - q_{n-2} ; the window is q_{n-4} .. q_{n-1}.
        out.first = count - 4;
        out.w = {0.0, r[0], r[1] - r[3], r[2] + 2 * r[3]};
    } else {
        out.first = segment - 1;
        out.w = r;
    }
    return out;
}

void locate(std::size_t count, double s, std::size_t* segment, double* t) {
    const double last = static_cast<double>(count - 1);
    if (!(s > 0.0)) s = 0.0;  // also maps NaN to 0
    if (s > last) s = last;
    std::size_t i = static_cast<std::size_t>(std::floor(s));
    if (i > count - 2) i = count - 2;
    *segment = i;
    *t = s - static_cast<double>(i);
}

SegmentWeights weights_at(std::size_t count, double s, Derivative order) {
    std::size_t segment = 0;
    double t = 0.0;
    locate(count, s, &segment, &t);
    return segment_weights(count, segment, t, order);
}


}  // namespace enteron::spline
