#include "mechanics/mesentery_force.h"

#include <cmath>

namespace enteron::mechanics {

MesenteryForce::MesenteryForce(const AxisModel& model, const MesenteryParameters& parameters,
                               const State& initial, std::pmr::memory_resource* memory)
    : stiffness_(parameters.stiffness), springs_(memory) {
    const std::size_t n = model.control_points;
    const std::size_t count = parameters.attachments;
    springs_.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const double fraction = (static_cast<double>(k) + 0.5) / static_cast<double>(count);
        Spring spring;
        spring.weights = spline::weights_at(n, fraction * static_cast<double>(n - 1),
                                            spline::Derivative::value, model.ends);
        spring.root = parameters.root_start + fraction * (parameters.root_end - parameters.root_start);
        spring.rest_length =
            parameters.rest_length > 0.0 ? parameters.rest_length : stretch_vector(initial, spring).norm();
        springs_.push_back(spring);
    }
}

Vec3 MesenteryForce::stretch_vector(const State& state, const Spring& spring) {
    return spline::evaluate(state.q.data(), spring.weights) - spring.root;
}

void MesenteryForce::evaluate(const State& state, double* force, const Linearization* lin) {
    for (const Spring& spring : springs_) {
        const Vec3 d = stretch_vector(state, spring);
        const double length = d.norm();
        if (!(length > spring.rest_length)) continue;  // slack (or NaN: the guard sees it)
        const double inv = 1.0 / length;
        const Vec3 u = d * inv;
        const double tension = stiffness_ * (length - spring.rest_length);
        const spline::SegmentWeights& sw = spring.weights;
        add_point_force(sw, -tension * u, force);
        if (lin != nullptr) {
            const double transverse = stiffness_ * (1.0 - spring.rest_length * inv);
            const double axial = stiffness_ - transverse;
            add_axial_block(*lin->system, sw, u, axial, transverse, lin->h * lin->h);
            const Vec3 velocity = spline::evaluate(state.v.data(), sw);
            add_point_force(sw, axial_times(u, axial, transverse, velocity), lin->stiffness_times_velocity);
        }
    }
}

double MesenteryForce::potential_energy(const State& state) const {
    double energy = 0.0;
    for (const Spring& spring : springs_) {
        const double excess = stretch_vector(state, spring).norm() - spring.rest_length;
        if (excess > 0.0) energy += 0.5 * stiffness_ * excess * excess;
    }
    return energy;
}

void MesenteryForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    // H <= k I for every spring, so per coordinate k w w^T bounds it.
    for (const Spring& spring : springs_) {
        const spline::SegmentWeights& sw = spring.weights;
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k <= j; ++k)
                bound.add(sw.first + j, sw.first + k, stiffness_ * sw.w[j] * sw.w[k]);
    }
}

}  // namespace enteron::mechanics
