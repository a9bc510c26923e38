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
                                            spline::Derivative::value);
        for (int c = 0; c < 3; ++c)
            spring.root[c] = parameters.root_start[c] +
                             fraction * (parameters.root_end[c] - parameters.root_start[c]);
        spring.rest_length = 0.0;
        double d[3];
        const double length = stretch_vector(initial, spring, d);
        spring.rest_length = parameters.rest_length > 0.0 ? parameters.rest_length : length;
        springs_.push_back(spring);
    }
}

double MesenteryForce::stretch_vector(const State& state, const Spring& spring, double d[3]) const {
    spline::evaluate(state.q.data(), spring.weights, d);
    for (int c = 0; c < 3; ++c) d[c] -= spring.root[c];
    return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

void MesenteryForce::evaluate(const State& state, double* force, const Linearization* lin) {
    for (const Spring& spring : springs_) {
        double d[3];
        const double length = stretch_vector(state, spring, d);
        if (!(length > spring.rest_length)) continue;  // slack (or NaN: the guard sees it)
        const double inv = 1.0 / length;
        const double u[3] = {d[0] * inv, d[1] * inv, d[2] * inv};
        const double tension = stiffness_ * (length - spring.rest_length);
        const spline::SegmentWeights& sw = spring.weights;
        const double f[3] = {-tension * u[0], -tension * u[1], -tension * u[2]};
        add_point_force(sw, f, force);
        if (lin != nullptr) {
            const double transverse = stiffness_ * (1.0 - spring.rest_length * inv);
            const double axial = stiffness_ - transverse;
            add_axial_block(*lin->system, sw, u, axial, transverse, lin->h * lin->h);
            double velocity[3], hv[3];
            spline::evaluate(state.v.data(), sw, velocity);
            axial_times(u, axial, transverse, velocity, hv);
            add_point_force(sw, hv, lin->stiffness_times_velocity);
        }
    }
}

double MesenteryForce::potential_energy(const State& state) const {
    double energy = 0.0;
    for (const Spring& spring : springs_) {
        double d[3];
        const double excess = stretch_vector(state, spring, d) - spring.rest_length;
        if (excess > 0.0) energy += 0.5 * stiffness_ * excess * excess;
    }
    return energy;
}

void MesenteryForce::add_stiffness_bound(spline::ScalarBandMatrix& bound) const {
    // H <= k I for every spring, so per coordinate k w w^T bounds it.
    for (const Spring& spring : springs_) {
        const spline::SegmentWeights& sw = spring.weights;
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k <= j; ++k)
                bound.add(sw.first + j, sw.first + k, stiffness_ * sw.w[j] * sw.w[k]);
    }
}

}  // namespace enteron::mechanics
