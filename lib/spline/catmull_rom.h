// SPDX-License-Identifier: Apache-2.0
// Uniform cubic Catmull-Rom spline through control points q_0 .. q_{n-1}.
//
// Segment i (0 <= i <= n-2) joins q_i to q_{i+1}; the global parameter s runs over
// [0, n-1] and segment i covers [i, i+1] with local t = s - i. On segment i
//   P(t) = 1/2 [(-t^3+2t^2-t) q_{i-1} + (3t^3-5t^2+2) q_i + (-3t^3+4t^2+t) q_{i+1} + (t^3-t^2) q_{i+2}].
//
// End treatment: a phantom point beyond each end, a fixed combination of the real points
// next to it (Ends, per end):
//   linear (the default)  q_{-1} = 2 q_0 - q_1            the end tangent is the end chord
//   quadratic             q_{-1} = 3 q_0 - 3 q_1 + q_2    the phantom continues the parabola
//                                                          through q_0, q_1, q_2
// and the same at the last end (q_n from q_{n-1}, q_{n-2}, q_{n-3}). Both reproduce straight
// evenly spaced points exactly (a straight bowel at rest has no bending energy) and keep the
// basis a linear map of the real control points only, so the mass matrix keeps half
// bandwidth 3. Folding the phantoms into their neighbours makes every segment a combination
// of four consecutive real points q_first .. q_first+3.
//
// Why two: with the linear phantom, d2P/dt2 on the end segment is (3t - 1) (q_0 - 2 q_1 + q_2):
// it changes sign a third of the way along, so the end segment cannot carry the curvature
// that is largest at a clamp, and a clamped beam converges at first order only. The
// quadratic phantom reproduces parabolas: its end segment is the parabola through q_0, q_1,
// q_2 (d2P/dt2 = q_0 - 2 q_1 + q_2), with the end tangent (4 q_1 - 3 q_0 - q_2) / 2, and a
// clamp holding that tangent converges at second order (mechanics/clamped_ends.h,
// docs/architecture.md).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "base/geometry.h"

namespace enteron::spline {

// Weights of four consecutive control points at one parameter of one segment.
struct SegmentWeights {
    std::size_t first = 0;          // index of the control point that w[0] multiplies
    std::array<double, 4> w{};      // w[k] multiplies q_{first+k}
};

// Derivative order of the weights: the point, dP/dt, or d2P/dt2 (t the segment parameter).
enum class Derivative { value = 0, first = 1, second = 2 };

// Smallest number of control points a spline may have (four points per segment).
constexpr std::size_t kMinControlPoints = 4;

// The raw uniform Catmull-Rom weights of q_{i-1}, q_i, q_{i+1}, q_{i+2} at t in [0, 1].
inline std::array<double, 4> raw_weights(double t, Derivative order) {
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

// How the spline continues past each end (see the top of this file).
enum class EndTreatment { linear, quadratic };
struct Ends {
    EndTreatment first = EndTreatment::linear;
    EndTreatment last = EndTreatment::linear;
};

// The weights on real control points for segment `segment` of a spline of `count` points
// (count >= 4, segment <= count - 2), phantom points folded in.
inline SegmentWeights segment_weights(std::size_t count, std::size_t segment, double t, Derivative order,
                                      Ends ends = {}) {
    const std::array<double, 4> r = raw_weights(t, order);
    SegmentWeights out;
    // With count >= 4 the first and the last segment are never the same one.
    if (segment == 0) {
        // The window is q_0 .. q_3.
        out.first = 0;
        if (ends.first == EndTreatment::linear)  // q_{-1} = 2 q_0 - q_1
            out.w = {r[1] + 2 * r[0], r[2] - r[0], r[3], 0.0};
        else  // q_{-1} = 3 q_0 - 3 q_1 + q_2
            out.w = {r[1] + 3 * r[0], r[2] - 3 * r[0], r[3] + r[0], 0.0};
    } else if (segment + 2 == count) {
        // The window is q_{n-4} .. q_{n-1}.
        out.first = count - 4;
        if (ends.last == EndTreatment::linear)  // q_n = 2 q_{n-1} - q_{n-2}
            out.w = {0.0, r[0], r[1] - r[3], r[2] + 2 * r[3]};
        else  // q_n = 3 q_{n-1} - 3 q_{n-2} + q_{n-3}
            out.w = {0.0, r[0] + r[3], r[1] - 3 * r[3], r[2] + 3 * r[3]};
    } else {
        out.first = segment - 1;
        out.w = r;
    }
    return out;
}

// Splits a global parameter s in [0, count-1] into a segment and its local t in [0, 1].
// Values outside the range are clamped to it.
inline void locate(std::size_t count, double s, std::size_t* segment, double* t) {
    const double last = static_cast<double>(count - 1);
    if (!(s > 0.0)) s = 0.0;  // also maps NaN to 0
    if (s > last) s = last;
    std::size_t i = static_cast<std::size_t>(std::floor(s));
    if (i > count - 2) i = count - 2;
    *segment = i;
    *t = s - static_cast<double>(i);
}

// Weights on real control points at global parameter s.
inline SegmentWeights weights_at(std::size_t count, double s, Derivative order, Ends ends = {}) {
    std::size_t segment = 0;
    double t = 0.0;
    locate(count, s, &segment, &t);
    return segment_weights(count, segment, t, order, ends);
}

// The point sum_k w[k] q_{first+k} of control points stored x y z per point. A tuned kernel
// (every contact and node calls it), kept as a loop: the sum of Eigen's weighted columns
// gives the same bits but was 7 to 11 % slower in the skins, and a product of Maps sums in
// another order (other last bits).
inline Vec3 evaluate(const double* points_xyz, const SegmentWeights& weights) {
    const double* q = points_xyz + 3 * weights.first;
    Vec3 out;
    for (int c = 0; c < 3; ++c)
        out[c] = weights.w[0] * q[c] + weights.w[1] * q[3 + c] + weights.w[2] * q[6 + c] +
                 weights.w[3] * q[9 + c];
    return out;
}

}  // namespace enteron::spline
