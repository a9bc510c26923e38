// SPDX-License-Identifier: Apache-2.0
// The implicit system's blocks of the axis' own axial laws, the stretch spring and the
// axial damper. Both act at the same two Gauss nodes of every segment, through the same
// derivative weights w and along the same unit tangent u, each with a block
// (w w^T) (x) (a u u^T + b I). Their coefficients are summed here per node and each
// segment's block then goes into the system in one pass over the band, instead of one
// pass per law (the pass costs more than both laws' own arithmetic).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/system_matrix.h"
#include "spline/segment_quadrature.h"

namespace enteron::mechanics {

class AxialBlocks {
public:
    static constexpr std::size_t kNodesPerSegment = 2;

    // The nodes of a 2-point Gauss rule on the first derivative of each segment, in
    // segment order, tube after tube (the laws' own nodes, tube_quadrature.h).
    AxialBlocks(const AxisModel& model, std::pmr::memory_resource* memory);

    // Forgets every coefficient and tangent (in O(1): the blocks of older rounds no longer count).
    void clear() { round_ += 1; }

    // True once a law has given the tangent at node k since clear().
    bool has_tangent(std::size_t k) const { return blocks_[k].round == round_; }

    // Adds a u u^T + b I at node k, u its unit tangent: the first law to add at a node
    // sets it, the others share it (the same axis, the same weights) and u is not read.
    void add(std::size_t k, const Vec3& u, double a, double b) {
        Block& block = blocks_[k];
        if (block.round != round_) {
            block.u = u;
            block.a = block.b = 0.0;
            block.round = round_;
        }
        block.a += a;
        block.b += b;
    }

    // system += sum over nodes of (w w^T) (x) (a u u^T + b I).
    void add_to(SystemMatrix& system) const;

private:
    struct Block {
        Vec3 u = Vec3::Zero();
        double a = 0.0;
        double b = 0.0;
        uint64_t round = 0;  // of the last add; the block counts only in the current round
    };
    std::pmr::vector<spline::QuadratureNode> nodes_;
    std::pmr::vector<Block> blocks_;
    uint64_t round_ = 1;
};

}  // namespace enteron::mechanics
