// SPDX-License-Identifier: Apache-2.0
#include "mechanics/axial_blocks.h"

#include "mechanics/tube_quadrature.h"

namespace enteron::mechanics {

AxialBlocks::AxialBlocks(const AxisModel& model, std::pmr::memory_resource* memory)
    : nodes_(tube_quadrature(model, spline::Derivative::first, kNodesPerSegment, memory).nodes),
      blocks_(nodes_.size(), Block{}, memory) {}

void AxialBlocks::add_to(SystemMatrix& system) const {
    static_assert(kNodesPerSegment == 2, "the nodes are paired by segment");
    for (std::size_t first = 0; first < nodes_.size(); first += kNodesPerSegment) {
        // A node no law reached (or whose tangent vanished) adds nothing.
        const bool live[2] = {has_tangent(first), has_tangent(first + 1)};
        if (!live[0] && !live[1]) continue;
        const Vec3 none = Vec3::Zero();
        const Block& b0 = blocks_[first];
        const Block& b1 = blocks_[first + 1];
        add_axial_block_pair(system, nodes_[first].weights, live[0] ? b0.u : none, live[0] ? b0.a : 0.0,
                             live[0] ? b0.b : 0.0, nodes_[first + 1].weights, live[1] ? b1.u : none,
                             live[1] ? b1.a : 0.0, live[1] ? b1.b : 0.0);
    }
}

}  // namespace enteron::mechanics
