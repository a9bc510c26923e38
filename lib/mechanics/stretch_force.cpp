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
    // The nodes of one segment share their four control points: their stiffness blocks go
    // into the system together (add_axial_block_pair).
    static_assert(kNodesPerSegment == 2, "the nodes are paired by segment");
    const std::size_t count = nodes_.size();
    for (std::size_t first = 0; first < count; first += kNodesPerSegment) {
        double u[2][3] = {}, axial[2] = {}, transverse[2] = {};
        for (std::size_t m = 0; m < kNodesPerSegment; ++m) {
            const spline::QuadratureNode& node = nodes_[first + m];
            const spline::SegmentWeights& sw = node.weights;
            double d[3];
            tangent(q, sw, d);
            const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (!(len > tiny)) continue;
            const double inv = 1.0 / len;
            for (int c = 0; c < 3; ++c) u[m][c] = d[c] * inv;
            const double strain = len / l0 - 1.0;
            const double tension = ea * strain;  // N
            const double scale = node.weight * tension;
            const double f[3] = {-scale * u[m][0], -scale * u[m][1], -scale * u[m][2]};
            add_point_force(sw, f, force);
            if (lin != nullptr) {
                transverse[m] = ea * std::max(strain, 0.0) * inv;
                axial[m] = ea / l0 - transverse[m];
                double rate[3], hr[3];
                tangent(state.v.data(), sw, rate);
                axial_times(u[m], node.weight * axial[m], node.weight * transverse[m], rate, hr);
                add_point_force(sw, hr, lin->stiffness_times_velocity);
            }
        }
        if (lin != nullptr) {
            const spline::QuadratureNode& n0 = nodes_[first];
            const spline::QuadratureNode& n1 = nodes_[first + 1];
            const double s0 = lin->h * lin->h * n0.weight, s1 = lin->h * lin->h * n1.weight;
            add_axial_block_pair(*lin->system, n0.weights, u[0], s0 * axial[0], s0 * transverse[0],
                                 n1.weights, u[1], s1 * axial[1], s1 * transverse[1]);
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
