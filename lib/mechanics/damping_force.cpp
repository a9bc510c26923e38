#include "mechanics/damping_force.h"

#include <cmath>

namespace enteron::mechanics {

namespace {
constexpr std::size_t kNodesPerSegment = 2;  // see stretch_force.h
}

DampingForce::DampingForce(const AxisModel& model, const DampingCoefficients& coefficients,
                           std::pmr::memory_resource* memory)
    : model_(model),
      coefficients_(coefficients),
      constant_(memory),
      nodes_(spline::segment_quadrature(model.control_points, spline::Derivative::first,
                                        kNodesPerSegment, memory)) {
    const std::size_t n = model.control_points;
    const double l0 = model.rest_segment_length;
    constant_.resize(n);
    spline::add_gram_matrix(n, spline::Derivative::value, coefficients.drag * l0, constant_);
    spline::add_gram_matrix(n, spline::Derivative::second, coefficients.bend / (l0 * l0 * l0), constant_);
}

void DampingForce::evaluate(const State& state, double* force, const Linearization* lin) {
    add_per_coordinate_product(constant_, state.v.data(), -1.0, force);

    const double l0 = model_.rest_segment_length;
    const double c = coefficients_.stretch;
    const double tiny = 1e-12 * l0;
    // With d = dP/dt and u = d / |d|: the force -c w (u . rate / l0) u and the block
    // (c / l0) u u^T are both d (d . x) / |d|^2 forms, so no square root is needed.
    // The two nodes of a segment share their four control points: their blocks go into the
    // system together (add_axial_block_pair).
    static_assert(kNodesPerSegment == 2, "the nodes are paired by segment");
    const std::size_t count = nodes_.size();
    for (std::size_t first = 0; first < count; first += kNodesPerSegment) {
        double d[2][3] = {}, axial[2] = {};
        for (std::size_t m = 0; m < kNodesPerSegment; ++m) {
            const spline::QuadratureNode& node = nodes_[first + m];
            const spline::SegmentWeights& sw = node.weights;
            double rate[3];
            spline::evaluate(state.q.data(), sw, d[m]);
            const double length2 = d[m][0] * d[m][0] + d[m][1] * d[m][1] + d[m][2] * d[m][2];
            if (!(length2 > tiny * tiny)) {  // no direction: the node adds nothing
                d[m][0] = d[m][1] = d[m][2] = 0.0;
                continue;
            }
            const double inv2 = 1.0 / length2;
            spline::evaluate(state.v.data(), sw, rate);
            // node.weight c (u . rate) / l0 along u, as a multiple of d
            const double scale =
                node.weight * c * (d[m][0] * rate[0] + d[m][1] * rate[1] + d[m][2] * rate[2]) * inv2 / l0;
            const double f[3] = {-scale * d[m][0], -scale * d[m][1], -scale * d[m][2]};
            add_point_force(sw, f, force);
            if (lin != nullptr) axial[m] = lin->h * node.weight * (c / l0) * inv2;
        }
        if (lin != nullptr)
            add_axial_block_pair(*lin->system, nodes_[first].weights, d[0], axial[0], 0.0,
                                 nodes_[first + 1].weights, d[1], axial[1], 0.0);
    }
}

void DampingForce::add_constant_linearization(double h, SystemMatrix& system) const {
    add_per_coordinate(constant_, h, system);
}

void DampingForce::add_damping_bound(spline::ScalarBandMatrix& bound) const {
    bound.add_scaled(constant_, 1.0);
    spline::add_gram_matrix(model_.control_points, spline::Derivative::first,
                            coefficients_.stretch / model_.rest_segment_length, bound);
}

}  // namespace enteron::mechanics
