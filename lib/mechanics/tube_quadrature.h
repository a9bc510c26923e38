// SPDX-License-Identifier: Apache-2.0
// The Gauss nodes of every tube of the axis (axis_model.h) back to back, tube after tube,
// each node's weights on the state's own control points, and the range of nodes of each
// tube with its rest segment length: the integration grid of the laws that are not
// quadratic in q (stretch, axial damping) and of their shared blocks (axial_blocks.h).
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "spline/segment_quadrature.h"

namespace enteron::mechanics {

// The nodes [begin, end) belong to one tube, whose segments are rest_segment_length long.
struct TubeNodeRange {
    std::size_t begin = 0;
    std::size_t end = 0;
    double rest_segment_length = 0.0;  // m
};

struct TubeQuadrature {
    std::pmr::vector<spline::QuadratureNode> nodes;
    std::pmr::vector<TubeNodeRange> tubes;
};

// `points_per_segment` nodes of a Gauss rule (spline/segment_quadrature.h) on every segment of
// every tube.
inline TubeQuadrature tube_quadrature(const AxisModel& model, spline::Derivative order,
                                      std::size_t points_per_segment, std::pmr::memory_resource* memory) {
    TubeQuadrature out{std::pmr::vector<spline::QuadratureNode>(memory), std::pmr::vector<TubeNodeRange>(memory)};
    const std::vector<TubeModel> tubes = model.tube_list();
    std::size_t total = 0;
    for (const TubeModel& tube : tubes) total += (tube.control_points - 1) * points_per_segment;
    out.nodes.reserve(total);
    for (const TubeModel& tube : tubes) {
        const std::size_t begin = out.nodes.size();
        spline::append_segment_quadrature(tube.control_points, order, points_per_segment, tube.ends, tube.first,
                                          out.nodes);
        out.tubes.push_back({begin, out.nodes.size(), tube.rest_segment_length});
    }
    return out;
}

}  // namespace enteron::mechanics
