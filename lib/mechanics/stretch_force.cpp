// SPDX-License-Identifier: Apache-2.0
#include "mechanics/stretch_force.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mechanics/axial_blocks.h"

namespace enteron::mechanics {

StretchForce::StretchForce(const AxisModel& model, double stretch_stiffness,
                           std::pmr::memory_resource* memory)
    : model_(model), stiffness_(stretch_stiffness), nodes_(memory), tubes_(memory), node_stiffness_(memory) {
    TubeQuadrature quadrature =
        tube_quadrature(model, spline::Derivative::first, AxialBlocks::kNodesPerSegment, memory);
    nodes_ = std::move(quadrature.nodes);
    tubes_ = std::move(quadrature.tubes);
    const std::vector<TubeModel> tubes = model.tube_list();
    node_stiffness_.reserve(nodes_.size());
    for (std::size_t k = 0; k < tubes.size(); ++k) {
        const TubeModel& tube = tubes[k];
        for (std::size_t i = tubes_[k].begin; i < tubes_[k].end; ++i)
            node_stiffness_.push_back(tube.stretch_stiffness_profile != nullptr
                                          ? tube.stretch_stiffness_profile->at(tube.rest_segment_length *
                                                                               nodes_[i].parameter)
                                          : TubeModel::own_or(tube.stretch_stiffness, stretch_stiffness));
    }
}

void StretchForce::evaluate(const State& state, double* force, const Linearization* lin) {
    for (const TubeNodeRange& tube : tubes_) evaluate_tube(state, tube, force, lin);
}

void StretchForce::evaluate_tube(const State& state, const TubeNodeRange& tube, double* force,
                                 const Linearization* lin) {
    const double* q = state.q.data();
    const double l0 = tube.rest_segment_length;
    const double inverse_l0 = 1.0 / l0;
    // A tangent shorter than this has no direction: the node adds nothing (degenerate shape).
    const double tiny = 1e-12 * l0;
    const double h_squared = lin != nullptr ? lin->h * lin->h : 0.0;
    // The nodes of one segment share their four control points: their forces are added
    // together (one read and write per coordinate). The square roots and divisions of both
    // nodes come before any store, so they overlap. The stiffness blocks go to the axial
    // blocks (axial_blocks.h), which add them to the system after this pass; a
    // linearisation without them (one law linearised alone) takes each block at once.
    static_assert(AxialBlocks::kNodesPerSegment == 2, "the nodes are paired by segment");
    AxialBlocks* blocks = lin != nullptr ? lin->axial : nullptr;
    for (std::size_t first = tube.begin; first < tube.end; first += AxialBlocks::kNodesPerSegment) {
        const spline::QuadratureNode* node = &nodes_[first];
        Vec3 d[2];  // dP/dt at the two nodes
        double len[2], inv[2];
        for (std::size_t m = 0; m < AxialBlocks::kNodesPerSegment; ++m) {
            d[m] = spline::evaluate(q, node[m].weights);
            len[m] = d[m].norm();
            inv[m] = 1.0 / std::max(len[m], tiny);
        }
        Vec3 f[2] = {Vec3::Zero(), Vec3::Zero()}, hr[2] = {Vec3::Zero(), Vec3::Zero()};
        for (std::size_t m = 0; m < AxialBlocks::kNodesPerSegment; ++m) {
            if (!(len[m] > tiny)) continue;  // no direction: the node adds nothing
            const double ea = node_stiffness_[first + m];
            const Vec3 u = d[m] * inv[m];
            const double strain = len[m] * inverse_l0 - 1.0;
            const double tension = ea * strain;  // N
            const double scale = node[m].weight * tension;
            f[m] = -scale * u;
            if (lin != nullptr) {
                const double transverse = ea * std::max(strain, 0.0) * inv[m];
                const double axial = ea * inverse_l0 - transverse;
                const Vec3 d_rate = spline::evaluate(state.v.data(), node[m].weights);  // d(dP/dt)/dt
                hr[m] = axial_times(u, node[m].weight * axial, node[m].weight * transverse, d_rate);
                const double a = h_squared * node[m].weight * axial, b = h_squared * node[m].weight * transverse;
                if (blocks != nullptr)
                    blocks->add(first + m, u, a, b);
                else
                    add_axial_block(*lin->system, node[m].weights, u, a, b, 1.0);
            }
        }
        add_point_force_pair(node[0].weights, f[0], node[1].weights, f[1], force);
        if (lin != nullptr)
            add_point_force_pair(node[0].weights, hr[0], node[1].weights, hr[1], lin->stiffness_times_velocity);
    }
}

double StretchForce::potential_energy(const State& state) const {
    double energy = 0.0;
    for (const TubeNodeRange& tube : tubes_) {
        const double l0 = tube.rest_segment_length;
        for (std::size_t k = tube.begin; k < tube.end; ++k) {
            const spline::QuadratureNode& node = nodes_[k];
            const double strain = spline::evaluate(state.q.data(), node.weights).norm() / l0 - 1.0;
            energy += node.weight * 0.5 * node_stiffness_[k] * strain * strain * l0;
        }
    }
    return energy;
}

void StretchForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    // At a node H <= EA/l0 I: the transverse factor eps/|P'| = eps / (l0 (1 + eps)) stays
    // below 1/l0. Per coordinate that is EA/l0 times the first-derivative Gram matrix.
    const double ea = stiffness_;
    add_tube_gram_matrices(
        model_, spline::Derivative::first, bound,
        [ea](const TubeModel& tube, bool profiled) {
            return (profiled ? 1.0 : TubeModel::own_or(tube.stretch_stiffness, ea)) / tube.rest_segment_length;
        },
        [](const TubeModel& tube) { return tube.stretch_stiffness_profile; });
}

}  // namespace enteron::mechanics
