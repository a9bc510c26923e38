// SPDX-License-Identifier: Apache-2.0
#include "mechanics/damping_force.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mechanics/axial_blocks.h"

namespace enteron::mechanics {

DampingForce::DampingForce(const AxisModel& model, const DampingCoefficients& coefficients,
                           std::pmr::memory_resource* memory)
    : model_(model),
      coefficients_(coefficients),
      constant_(memory),
      constant_products_(memory),
      nodes_(memory),
      tubes_(memory) {
    TubeQuadrature quadrature =
        tube_quadrature(model, spline::Derivative::first, AxialBlocks::kNodesPerSegment, memory);
    nodes_ = std::move(quadrature.nodes);
    tubes_ = std::move(quadrature.tubes);
    constant_.resize(model.control_points);
    for (const TubeModel& tube : model.tube_list()) {
        const std::size_t n = tube.control_points;
        const double l0 = tube.rest_segment_length;
        spline::add_gram_matrix(n, spline::Derivative::value, coefficients.drag * l0, constant_, tube.ends, nullptr,
                                0.0, tube.first);
        spline::add_gram_matrix(n, spline::Derivative::second, coefficients.bend / (l0 * l0 * l0), constant_,
                                tube.ends, nullptr, 0.0, tube.first);
    }
    constant_products_.assign(constant_);
}

void DampingForce::evaluate(const State& state, double* force, const Linearization* lin) {
    constant_products_.multiply_add(state.v.data(), -1.0, force);
    for (const TubeNodeRange& tube : tubes_) evaluate_tube(state, tube, force, lin);
}

void DampingForce::evaluate_tube(const State& state, const TubeNodeRange& tube, double* force,
                                 const Linearization* lin) {
    const double l0 = tube.rest_segment_length;
    const double c = coefficients_.stretch;
    const double c_per_l0 = c / l0;
    const double tiny = 1e-12 * l0, tiny2 = tiny * tiny;
    // With d = dP/dt and u = d / |d|: the force -c w (u . rate / l0) u is a d (d . x) / |d|^2
    // form, so no square root is needed for it. The block (c / l0) u u^T goes to the axial
    // blocks (axial_blocks.h), which usually have the tangent from the stretch already; a
    // linearisation without them (one law linearised alone) takes each block at once.
    // The two nodes of a segment share their four control points: their forces are added
    // together, and both divisions come before any store (they overlap).
    static_assert(AxialBlocks::kNodesPerSegment == 2, "the nodes are paired by segment");
    AxialBlocks* blocks = lin != nullptr ? lin->axial : nullptr;
    for (std::size_t first = tube.begin; first < tube.end; first += AxialBlocks::kNodesPerSegment) {
        const spline::QuadratureNode* node = &nodes_[first];
        Vec3 d[2];  // dP/dt at the two nodes
        Vec3 f[2] = {Vec3::Zero(), Vec3::Zero()};
        double length2[2], inv2[2];
        for (std::size_t m = 0; m < AxialBlocks::kNodesPerSegment; ++m) {
            d[m] = spline::evaluate(state.q.data(), node[m].weights);
            length2[m] = d[m].squaredNorm();
            inv2[m] = 1.0 / std::max(length2[m], tiny2);
        }
        for (std::size_t m = 0; m < AxialBlocks::kNodesPerSegment; ++m) {
            if (!(length2[m] > tiny2)) continue;  // no direction: the node adds nothing
            const Vec3 d_rate = spline::evaluate(state.v.data(), node[m].weights);  // d(dP/dt)/dt
            // node.weight c (u . d_rate) / l0 along u, as a multiple of d
            const double scale = node[m].weight * c_per_l0 * d[m].dot(d_rate) * inv2[m];
            f[m] = -scale * d[m];
            if (lin == nullptr) continue;
            Vec3 u = Vec3::Zero();
            if (blocks == nullptr || !blocks->has_tangent(first + m)) u = d[m] * (1.0 / std::sqrt(length2[m]));
            const double a = lin->h * node[m].weight * c_per_l0;
            if (blocks != nullptr)
                blocks->add(first + m, u, a, 0.0);
            else
                add_axial_block(*lin->system, node[m].weights, u, a, 0.0, 1.0);
        }
        add_point_force_pair(node[0].weights, f[0], node[1].weights, f[1], force);
    }
}

void DampingForce::add_constant_linearization(double h, SystemMatrix& system) const {
    add_per_coordinate(constant_, h, system);
}

void DampingForce::add_damping_bound(numerics::ScalarBandMatrix& bound) const {
    bound.add_scaled(constant_, 1.0);
    const double c = coefficients_.stretch;
    add_tube_gram_matrices(
        model_, spline::Derivative::first, bound,
        [c](const TubeModel& tube, bool /*profiled*/) { return c / tube.rest_segment_length; },
        [](const TubeModel& /*tube*/) { return static_cast<const spline::LengthProfile*>(nullptr); });
}

}  // namespace enteron::mechanics
