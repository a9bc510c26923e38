// SPDX-License-Identifier: Apache-2.0
#include "spline/segment_quadrature.h"

#include <stdexcept>

#include "numerics/gauss_legendre.h"

namespace enteron::spline {

namespace {

template <std::size_t M>
void fill(std::size_t count, Derivative order, Ends ends, std::size_t first,
          std::pmr::vector<QuadratureNode>& out) {
    constexpr auto rule = numerics::gauss_legendre<M>();
    for (std::size_t segment = 0; segment + 1 < count; ++segment) {
        // An end segment with the quadratic treatment: every node at its midpoint (see the header).
        const bool quadratic_end = (segment == 0 && ends.first == EndTreatment::quadratic) ||
                                   (segment + 2 == count && ends.last == EndTreatment::quadratic);
        for (const auto& node : rule) {
            const double t = quadratic_end ? 0.5 : node.t;
            SegmentWeights weights = segment_weights(count, segment, t, order, ends);
            weights.first += first;
            out.push_back({weights, node.weight, double(segment) + t});
        }
    }
}

}  // namespace

std::pmr::vector<QuadratureNode> segment_quadrature(std::size_t count, Derivative order,
                                                    std::size_t points_per_segment,
                                                    std::pmr::memory_resource* memory, Ends ends) {
    std::pmr::vector<QuadratureNode> nodes(memory);
    nodes.reserve((count - 1) * points_per_segment);
    append_segment_quadrature(count, order, points_per_segment, ends, 0, nodes);
    return nodes;
}

void append_segment_quadrature(std::size_t count, Derivative order, std::size_t points_per_segment, Ends ends,
                               std::size_t first, std::pmr::vector<QuadratureNode>& out) {
    switch (points_per_segment) {
        case 2: fill<2>(count, order, ends, first, out); break;
        case 3: fill<3>(count, order, ends, first, out); break;
        case 4: fill<4>(count, order, ends, first, out); break;
        case 5: fill<5>(count, order, ends, first, out); break;
        default: throw std::invalid_argument("segment_quadrature: 2 to 5 points per segment");
    }
}

}  // namespace enteron::spline
