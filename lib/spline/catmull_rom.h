// Uniform cubic Catmull-Rom spline through control points q_0 .. q_{n-1}.
//
// Segment i (0 <= i <= n-2) joins q_i to q_{i+1}; the global parameter s runs over
// [0, n-1] and segment i covers [i, i+1] with local t = s - i. On segment i
//   P(t) = 1/2 [(-t^3+2t^2-t) q_{i-1} + (3t^3-5t^2+2) q_i + (-3t^3+4t^2+t) q_{i+1} + (t^3-t^2) q_{i+2}].
//
// End treatment: phantom points by linear extrapolation, q_{-1} = 2 q_0 - q_1 and
// q_n = 2 q_{n-1} - q_{n-2}. The spline then reproduces straight evenly spaced points
// exactly (a straight bowel at rest has no bending energy), its end tangents are the end
// chords, and the basis stays a linear map of the real control points only, so the mass
// matrix keeps half bandwidth 3. Folding the phantoms into their neighbours makes every
// segment a combination of four consecutive real points q_first .. q_first+3.
#pragma once

#include <array>
#include <cstddef>

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
std::array<double, 4> raw_weights(double t, Derivative order);

// The weights on real control points for segment `segment` of a spline of `count` points
// (count >= 4, segment <= count - 2), phantom points folded in.
SegmentWeights segment_weights(std::size_t count, std::size_t segment, double t, Derivative order);

// Splits a global parameter s in [0, count-1] into a segment and its local t in [0, 1].
// Values outside the range are clamped to it.
void locate(std::size_t count, double s, std::size_t* segment, double* t);

// Weights on real control points at global parameter s.
SegmentWeights weights_at(std::size_t count, double s, Derivative order);

// Evaluates sum_k w[k] q_{first+k} for control points stored x y z per point.
inline void evaluate(const double* points_xyz, const SegmentWeights& weights, double out[3]) {
    const double* q = points_xyz + 3 * weights.first;
    for (int c = 0; c < 3; ++c)
        out[c] = weights.w[0] * q[c] + weights.w[1] * q[3 + c] + weights.w[2] * q[6 + c] +
                 weights.w[3] * q[9 + c];
}

}  // namespace enteron::spline
