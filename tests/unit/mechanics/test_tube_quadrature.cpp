// SPDX-License-Identifier: Apache-2.0
// The nodes of every tube (lib/mechanics/tube_quadrature.h): each tube's are those of its
// spline alone, after the tubes before it, their weights on the tube's own points of the state.
#include "mechanics/tube_quadrature.h"

#include <gtest/gtest.h>

#include <memory_resource>

namespace enteron::mechanics {
namespace {

TEST(TubeQuadrature, EachTubesNodesAreItsSplinesAloneOnItsOwnPoints) {
    AxisModel model;
    model.tubes = {TubeModel{0, 6, 0.1, 0.3, {}, nullptr, nullptr, nullptr, -1.0, -1.0},
                   TubeModel{6, 5, 0.05, 0.3, {spline::EndTreatment::linear, spline::EndTreatment::quadratic}, nullptr,
                             nullptr, nullptr, -1.0, -1.0}};
    model.control_points = 11;
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    const TubeQuadrature both = tube_quadrature(model, spline::Derivative::first, 2, memory);
    const auto first = spline::segment_quadrature(6, spline::Derivative::first, 2, memory);
    const auto second = spline::segment_quadrature(5, spline::Derivative::first, 2, memory, model.tubes[1].ends);
    ASSERT_EQ(both.tubes.size(), 2u);
    EXPECT_EQ(both.tubes[0].begin, 0u);
    EXPECT_EQ(both.tubes[0].end, first.size());
    EXPECT_EQ(both.tubes[1].begin, first.size());
    EXPECT_EQ(both.tubes[1].end, first.size() + second.size());
    EXPECT_EQ(both.tubes[1].rest_segment_length, 0.05);
    ASSERT_EQ(both.nodes.size(), first.size() + second.size());
    for (std::size_t k = 0; k < both.nodes.size(); ++k) {
        const bool in_second = k >= first.size();
        const spline::QuadratureNode& alone = in_second ? second[k - first.size()] : first[k];
        EXPECT_EQ(both.nodes[k].weights.first, alone.weights.first + (in_second ? 6u : 0u)) << k;
        EXPECT_EQ(both.nodes[k].weights.w, alone.weights.w) << k;
        EXPECT_EQ(both.nodes[k].weight, alone.weight) << k;
        EXPECT_EQ(both.nodes[k].parameter, alone.parameter) << k;
        // No node reaches past its tube's points.
        const std::size_t last = in_second ? 10u : 5u;
        EXPECT_LE(both.nodes[k].weights.first + 3, last) << k;
    }
}

}  // namespace
}  // namespace enteron::mechanics
