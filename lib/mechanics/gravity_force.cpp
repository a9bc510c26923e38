// SPDX-License-Identifier: Apache-2.0
#include "mechanics/gravity_force.h"

#include "base/state_io.h"

namespace enteron::mechanics {

GravityForce::GravityForce(const AxisModel& model, const Vec3& gravity,
                           std::pmr::memory_resource* memory)
    : gravity_(gravity), lumped_mass_(memory) {
    const std::size_t n = model.control_points;
    numerics::ScalarBandMatrix mass(memory);
    mass.resize(n);
    add_mass_matrix(model, mass);
    std::pmr::vector<double> ones(n, 1.0, memory);
    lumped_mass_.assign(n, 0.0);
    mass.multiply(ones.data(), lumped_mass_.data());
}

void GravityForce::evaluate(const State& /*state*/, double* force, const Linearization* /*lin*/) {
    for (std::size_t j = 0; j < lumped_mass_.size(); ++j)
        point_at(force, j) += lumped_mass_[j] * gravity_;
}

double GravityForce::potential_energy(const State& state) const {
    double energy = 0.0;
    for (std::size_t j = 0; j < lumped_mass_.size(); ++j)
        for (int c = 0; c < 3; ++c) energy -= lumped_mass_[j] * gravity_[c] * state.q[3 * j + c];
    return energy;
}

void GravityForce::save_state(StateWriter& out) const {
    out.begin_section("gravity", 1);
    out.f64s(gravity_.data(), 3);
    out.end_section();
}

void GravityForce::restore_state(StateReader& in) {
    in.begin_section("gravity", 1);
    Vec3 gravity;
    in.f64s("gravity", 3, gravity.data());
    in.end_section();
    if (!in.checking()) gravity_ = gravity;
}

}  // namespace enteron::mechanics
