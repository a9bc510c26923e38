#include "mechanics/stretch_force.h"

#include <algorithm>
#include <cmath>

namespace enteron::mechanics {

namespace {
constexpr std::size_t kNodesPerSegment = 2;  // see stretch_force.h

// dP/dt at a node: sum_k w_k q_{first+k}.
inline void tangent(const double* points, const spline::SegmentWeights& sw, double d[3]) {
    spline::evaluate(points, sw, d);
}
}  // namespace

StretchForce::StretchForce(const AxisModel& model, double stretch_stiffness,
                           std::pmr::memory_resource* memory)
    : model_(model),
      stiffness_(stretch_stiffness),
      nodes_(spline::segment_quadrature(model.control_points, spline::Derivative::first,
                                        kNodesPerSegment, memory)) {}

void StretchForce::evaluate(const State& state, double* force, const Linearization* lin) {
    const double* q = state.q.data();
    const double l0 = model_.rest_segment_length;
    const double ea = stiffness_;
    // A tangent shorter than this has no direction: the node adds nothing (degenerate shape).
    const double tiny = 1e-12 * l0;
    for (const spline::QuadratureNode& node : nodes_) {
        const spline::SegmentWeights& sw = node.weights;
        double d[3];
        tangent(q, sw, d);
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(len > tiny)) continue;
        const double inv = 1.0 / len;
        const double u[3] = {d[0] * inv, d[1] * inv, d[2] * inv};
        const double strain = len / l0 - 1.0;
        const double tension = ea * strain;  // N
        const double scale = node.weight * tension;
        const double f[3] = {-scale * u[0], -scale * u[1], -scale * u[2]};
        add_point_force(sw, f, force);
        if (lin != nullptr) {
            const double transverse = ea * std::max(strain, 0.0) * inv;
            const double axial = ea / l0 - transverse;
            add_axial_block(*lin->system, sw, u, axial, transverse, lin->h * lin->h * node.weight);
            double rate[3], hr[3];
            tangent(state.v.data(), sw, rate);
            axial_times(u, node.weight * axial, node.weight * transverse, rate, hr);
            add_point_force(sw, hr, lin->stiffness_times_velocity);
        }
    }
}

double StretchForce::potential_energy(const State& state) const {
    const double l0 = model_.rest_segment_length;
    double energy = 0.0;
    for (const spline::QuadratureNode& node : nodes_) {
        double d[3];
        tangent(state.q.data(), node.weights, d);
        const double strain = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / l0 - 1.0;
        energy += node.weight * 0.5 * stiffness_ * strain * strain * l0;
    }
    return energy;
}

void StretchForce::add_stiffness_bound(spline::ScalarBandMatrix& bound) const {
    // At a node H <= EA/l0 I: the transverse factor eps/|P'| = eps / (l0 (1 + eps)) stays
    // below 1/l0. Per coordinate that is EA/l0 times the first-derivative Gram matrix.
    spline::add_gram_matrix(model_.control_points, spline::Derivative::first,
                            stiffness_ / model_.rest_segment_length, bound);
}

}  // namespace enteron::mechanics
