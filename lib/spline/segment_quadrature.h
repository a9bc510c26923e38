// SPDX-License-Identifier: Apache-2.0
// Gauss quadrature nodes on every segment of the spline, with the basis weights of one
// derivative order precomputed at each node: the integration grid of the energies that
// are not quadratic in q (stretch, stretch damping).
//
// An end segment with the quadratic end treatment (a clamped end, catmull_rom.h) has all its
// nodes at its midpoint, where its tangent is exactly its chord (q_1 - q_0): a one-point
// rule. That segment is a parabola in t, whose parametric speed varies along it even where
// the bowel is evenly stretched (by about 0.3 phi^2 between the two Gauss nodes, phi the
// segment's turning angle), so a stiff stretch law measured at two nodes would forbid it to
// bend: membrane locking (a large-deflection cantilever, 2.5 cm segments, 16 degrees per
// segment at the clamp, came out 1.9 % too stiff at EA = 1e4 N and 5.8 % at 1e5 N). Measured
// at the midpoint, the stretch is the chord's, as for an interior segment to second order.
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "spline/catmull_rom.h"

namespace enteron::spline {

struct QuadratureNode {
    SegmentWeights weights;  // basis weights (of the chosen order) at this node
    double weight = 0.0;     // Gauss weight; the weights of one segment sum to 1
    double parameter = 0.0;  // where along the axis: segment + t (its rest arc length / l0)
};

// Nodes of a `points_per_segment`-point Gauss rule (2 to 5) on each of the count-1 segments.
std::pmr::vector<QuadratureNode> segment_quadrature(std::size_t count, Derivative order,
                                                    std::size_t points_per_segment,
                                                    std::pmr::memory_resource* memory, Ends ends = {});
// The same nodes appended to `out`, for a spline whose points start at `first` in the state
// (one tube of several, mechanics/axis_model.h): its weights' `first` are shifted so.
void append_segment_quadrature(std::size_t count, Derivative order, std::size_t points_per_segment, Ends ends,
                               std::size_t first, std::pmr::vector<QuadratureNode>& out);

}  // namespace enteron::spline
