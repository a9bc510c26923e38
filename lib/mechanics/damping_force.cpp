#include "mechanics/damping_force.h"

#include <algorithm>
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
                                        kNodesPerSegment, memory)),
      axial_nodes_(nodes_.size(), AxialNode{}, memory) {
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
    const double c_per_l0 = c / l0;
    const double tiny = 1e-12 * l0, tiny2 = tiny * tiny;
    // With d = dP/dt and u = d / |d|: the force -c w (u . rate / l0) u and the block
    // (c / l0) u u^T are both d (d . x) / |d|^2 forms, so no square root is needed.
    // The two nodes of a segment share their four control points: their forces are added
    // together, both divisions come before any store (they overlap), and the blocks go into
    // the system in a second pass, two at a time (add_axial_block_pair).
    static_assert(kNodesPerSegment == 2, "the nodes are paired by segment");
    const std::size_t count = nodes_.size();
    for (std::size_t first = 0; first < count; first += kNodesPerSegment) {
        const spline::QuadratureNode* node = &nodes_[first];
        double length2[2], inv2[2], f[2][3] = {};
        for (std::size_t m = 0; m < kNodesPerSegment; ++m) {
            double* d = axial_nodes_[first + m].d;
            spline::evaluate(state.q.data(), node[m].weights, d);
            length2[m] = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            inv2[m] = 1.0 / std::max(length2[m], tiny2);
        }
        for (std::size_t m = 0; m < kNodesPerSegment; ++m) {
            AxialNode& axial_node = axial_nodes_[first + m];
            double* d = axial_node.d;
            if (!(length2[m] > tiny2)) {  // no direction: the node adds nothing
                d[0] = d[1] = d[2] = 0.0;
                axial_node.axial = 0.0;
                continue;
            }
            double rate[3];
            spline::evaluate(state.v.data(), node[m].weights, rate);
            // node.weight c (u . rate) / l0 along u, as a multiple of d
            const double scale =
                node[m].weight * c_per_l0 * (d[0] * rate[0] + d[1] * rate[1] + d[2] * rate[2]) * inv2[m];
            for (int k = 0; k < 3; ++k) f[m][k] = -scale * d[k];
            if (lin != nullptr) axial_node.axial = lin->h * node[m].weight * c_per_l0 * inv2[m];
        }
        add_point_force_pair(node[0].weights, f[0], node[1].weights, f[1], force);
    }
    if (lin == nullptr) return;
    for (std::size_t first = 0; first < count; first += kNodesPerSegment) {
        const AxialNode* a = &axial_nodes_[first];
        add_axial_block_pair(*lin->system, nodes_[first].weights, a[0].d, a[0].axial, 0.0,
                             nodes_[first + 1].weights, a[1].d, a[1].axial, 0.0);
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
