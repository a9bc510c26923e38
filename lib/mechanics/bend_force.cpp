// SPDX-License-Identifier: Apache-2.0
#include "mechanics/bend_force.h"

#include <cmath>

namespace enteron::mechanics {

BendForce::BendForce(const AxisModel& model, double bend_stiffness, std::pmr::memory_resource* memory)
    : stiffness_(memory), stiffness_products_(memory), scratch_(3 * model.control_points, 0.0, memory) {
    stiffness_.resize(model.control_points);
    // With a profile EI(s) comes from it at each node (bend_stiffness is then its largest value).
    add_tube_gram_matrices(
        model, spline::Derivative::second, stiffness_,
        [bend_stiffness](const TubeModel& tube, bool profiled) {
            const double l0 = tube.rest_segment_length;
            return profiled ? 1.0 / (l0 * l0 * l0)
                            : TubeModel::own_or(tube.bend_stiffness, bend_stiffness) / (l0 * l0 * l0);
        },
        [](const TubeModel& tube) { return tube.bend_stiffness_profile; });
    stiffness_products_.assign(stiffness_);
}

void BendForce::evaluate(const State& state, double* force, const Linearization* lin) {
    if (lin != nullptr)  // K q and K v in one pass over K
        stiffness_products_.multiply_add(state.q.data(), -1.0, force, state.v.data(), 1.0,
                                         lin->stiffness_times_velocity);
    else
        stiffness_products_.multiply_add(state.q.data(), -1.0, force);
}

void BendForce::add_constant_linearization(double h, SystemMatrix& system) const {
    add_per_coordinate(stiffness_, h * h, system);
}

double BendForce::potential_energy(const State& state) const {
    // 1/2 q^T K_b q per coordinate, from the product K_b q.
    stiffness_products_.multiply(state.q.data(), scratch_.data());
    double energy = 0.0;
    for (std::size_t k = 0; k < scratch_.size(); ++k) energy += state.q[k] * scratch_[k];
    return 0.5 * energy;
}

void BendForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    bound.add_scaled(stiffness_, 1.0);
}

}  // namespace enteron::mechanics
