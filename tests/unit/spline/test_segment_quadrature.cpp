// SPDX-License-Identifier: Apache-2.0
// The quadrature grid over the spline's segments (lib/spline/segment_quadrature.h): each
// segment gets the rule's nodes with the basis weights of the asked derivative there, so
// that sum over nodes of weight * f(P(t)) is the integral over the axis' parameter: the
// length of a straight, evenly spaced axis, and the integral of |P'|^2 on a curved one,
// compared with a fine midpoint sum; a quadratic (clamped) end segment has every node at
// its midpoint; a rule of another size is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "spline/segment_quadrature.h"

namespace enteron::spline {
namespace {

// Control points of a planar arc (x y z each).
std::vector<double> arc(std::size_t count) {
    std::vector<double> q;
    for (std::size_t i = 0; i < count; ++i) {
        const double angle = 0.3 * double(i);
        q.insert(q.end(), {std::cos(angle), std::sin(angle), 0.05 * double(i * i)});
    }
    return q;
}

TEST(SegmentQuadrature, EverySegmentGetsTheRulesNodesAndWeights) {
    for (std::size_t points = 2; points <= 5; ++points) {
        const auto nodes = segment_quadrature(7, Derivative::value, points, std::pmr::new_delete_resource());
        ASSERT_EQ(nodes.size(), 6 * points);
        for (std::size_t segment = 0; segment < 6; ++segment) {
            double sum = 0.0;
            for (std::size_t k = 0; k < points; ++k) sum += nodes[segment * points + k].weight;
            EXPECT_NEAR(sum, 1.0, 1e-15) << points << " points, segment " << segment;
        }
        for (const QuadratureNode& node : nodes) {
            double partition = 0.0;  // the value weights sum to one (a partition of unity)
            for (double w : node.weights.w) partition += w;
            EXPECT_NEAR(partition, 1.0, 1e-15);
        }
    }
    EXPECT_THROW(segment_quadrature(7, Derivative::value, 6, std::pmr::new_delete_resource()), std::invalid_argument);
    EXPECT_THROW(segment_quadrature(7, Derivative::value, 1, std::pmr::new_delete_resource()), std::invalid_argument);
}

TEST(SegmentQuadrature, ItIntegratesOverTheAxisParameter) {
    const std::size_t count = 9;
    const std::vector<double> q = arc(count);
    // The integral of |P'(t)|^2 over every segment: a polynomial of degree 4 in t, so the
    // 3-point rule is exact; against a fine midpoint sum of the same spline.
    const auto nodes = segment_quadrature(count, Derivative::first, 3, std::pmr::new_delete_resource());
    double by_rule = 0.0;
    for (const QuadratureNode& node : nodes) by_rule += node.weight * evaluate(q.data(), node.weights).squaredNorm();
    double by_midpoints = 0.0;
    const int steps = 20000;
    for (std::size_t segment = 0; segment + 1 < count; ++segment)
        for (int k = 0; k < steps; ++k) {
            const double t = (k + 0.5) / steps;
            by_midpoints += evaluate(q.data(), segment_weights(count, segment, t, Derivative::first)).squaredNorm() / steps;
        }
    EXPECT_NEAR(by_rule, by_midpoints, 1e-8 * by_midpoints);
}

TEST(SegmentQuadrature, AQuadraticEndSegmentHasItsNodesAtItsMidpoint) {
    const std::size_t count = 8;
    const Ends clamped{EndTreatment::quadratic, EndTreatment::linear};
    const auto nodes = segment_quadrature(count, Derivative::first, 2, std::pmr::new_delete_resource(), clamped);
    const SegmentWeights middle = segment_weights(count, 0, 0.5, Derivative::first, clamped);
    for (int k = 0; k < 2; ++k) EXPECT_EQ(nodes[k].weights.w, middle.w) << "node " << k << " of the clamped segment";
    // There the tangent is the chord q_1 - q_0 (the parabola's mean-value point).
    const std::vector<double> q = arc(count);
    const Vec3 chord = point_at(q.data(), 1) - point_at(q.data(), 0);
    EXPECT_LT((evaluate(q.data(), nodes[0].weights) - chord).norm(), 1e-14);
    // The free last end keeps the two Gauss nodes.
    const std::size_t last = 2 * (count - 2);
    EXPECT_NE(nodes[last].weights.w, nodes[last + 1].weights.w);
}

}  // namespace
}  // namespace enteron::spline
