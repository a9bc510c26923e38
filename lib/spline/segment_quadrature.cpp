#include "spline/segment_quadrature.h"

#include <stdexcept>

#include "numerics/gauss_legendre.h"

namespace enteron::spline {

namespace {

template <std::size_t M>
void fill(std::size_t count, Derivative order, std::pmr::vector<QuadratureNode>& out) {
    constexpr auto rule = numerics::gauss_legendre<M>();
    for (std::size_t segment = 0; segment + 1 < count; ++segment)
        for (const auto& node : rule)
            out.push_back({segment_weights(count, segment, node.t, order), node.weight});
}

}  // namespace

std::pmr::vector<QuadratureNode> segment_quadrature(std::size_t count, Derivative order,
                                                    std::size_t points_per_segment,
                                                    std::pmr::memory_resource* memory) {
    std::pmr::vector<QuadratureNode> nodes(memory);
    nodes.reserve((count - 1) * points_per_segment);
    switch (points_per_segment) {
        case 2: fill<2>(count, order, nodes); break;
        case 3: fill<3>(count, order, nodes); break;
        case 4: fill<4>(count, order, nodes); break;
        case 5: fill<5>(count, order, nodes); break;
        default: throw std::invalid_argument("segment_quadrature: 2 to 5 points per segment");
    }
    return nodes;
}

}  // namespace enteron::spline
