// Gauss quadrature nodes on every segment of the spline, with the basis weights of one
// derivative order precomputed at each node: the integration grid of the energies that
// are not quadratic in q (stretch, stretch damping).
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "spline/catmull_rom.h"

namespace enteron::spline {

struct QuadratureNode {
    SegmentWeights weights;  // basis weights (of the chosen order) at this node
    double weight = 0.0;     // Gauss weight; the weights of one segment sum to 1
};

// Nodes of a `points_per_segment`-point Gauss rule (2 to 5) on each of the count-1 segments.
std::pmr::vector<QuadratureNode> segment_quadrature(std::size_t count, Derivative order,
                                                    std::size_t points_per_segment,
                                                    std::pmr::memory_resource* memory);

}  // namespace enteron::spline
