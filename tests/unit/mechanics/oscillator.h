// SPDX-License-Identifier: Apache-2.0
// Shared by the integrators' tests (lib/mechanics/implicit_euler.h, rk4.h,
// symplectic_euler.h, integrator.h): an axis whose every coordinate is a harmonic oscillator
// of angular frequency omega, so that each method can be checked against the closed form
//   q(t) = q0 cos(omega t) + v0 / omega sin(omega t).
// The force is F = -omega^2 M q with M the axis' own (banded, consistent) mass matrix: then
// M a = F gives a = -omega^2 q for every coordinate, whatever M couples. Its linearisation
// H = omega^2 M (constant) goes into the implicit system like any effect's.
#pragma once

#include <cmath>
#include <memory_resource>
#include <vector>

#include "base/memory.h"
#include "mechanics/dynamics.h"
#include "mechanics/effect.h"
#include "mechanics/integrator.h"
#include "spline/gram_matrix.h"

namespace mechanics_test {

namespace mech = enteron::mechanics;

class MassProportionalSpring final : public mech::Effect {
public:
    MassProportionalSpring(const mech::AxisModel& model, double omega, std::pmr::memory_resource* memory)
        : stiffness_(omega * omega), mass_(memory), scratch_(3 * model.control_points, 0.0) {
        mass_.resize(model.control_points);
        enteron::spline::add_gram_matrix(model.control_points, enteron::spline::Derivative::value,
                                         model.linear_density * model.rest_segment_length, mass_, model.ends);
    }
    mech::EffectId id() const override { return mech::EffectId::mesentery; }  // any id: only one effect
    void evaluate(const mech::State& state, double* force, const mech::Linearization* lin) override {
        mass_.multiply(state.q.data(), scratch_.data(), 3, 3);  // M q, x y z interleaved
        for (std::size_t k = 0; k < scratch_.size(); ++k) force[k] -= stiffness_ * scratch_[k];
        if (lin == nullptr) return;
        mass_.multiply(state.v.data(), scratch_.data(), 3, 3);
        for (std::size_t k = 0; k < scratch_.size(); ++k) lin->stiffness_times_velocity[k] += stiffness_ * scratch_[k];
    }
    void add_constant_linearization(double h, mech::SystemMatrix& system) const override {
        mech::add_per_coordinate(mass_, stiffness_ * h * h, system);
    }
    double potential_energy(const mech::State& state) const override {
        mass_.multiply(state.q.data(), scratch_.data(), 3, 3);
        double e = 0.0;
        for (std::size_t k = 0; k < scratch_.size(); ++k) e += 0.5 * stiffness_ * state.q[k] * scratch_[k];
        return e;
    }
    void add_stiffness_bound(enteron::numerics::ScalarBandMatrix& bound) const override {
        bound.add_scaled(mass_, stiffness_);
    }

private:
    double stiffness_;  // omega^2, 1/s^2
    enteron::numerics::ScalarBandMatrix mass_;
    mutable std::vector<double> scratch_;
};

constexpr std::size_t kOscillatorPoints = 8;

inline mech::AxisModel oscillator_model() {
    mech::AxisModel m;
    m.control_points = kOscillatorPoints;
    m.rest_segment_length = 0.05;
    m.linear_density = 0.3;
    return m;
}

// The axis as oscillators, each coordinate with its own start.
struct Oscillator {
    Oscillator(double omega, std::pmr::memory_resource* memory = std::pmr::new_delete_resource())
        : omega(omega), dynamics(oscillator_model(), memory), state(memory) {
        dynamics.add_effect(enteron::make_owned<MassProportionalSpring>(memory, oscillator_model(), omega, memory));
        dynamics.finalize();
        state.resize(kOscillatorPoints);
        for (std::size_t k = 0; k < state.q.size(); ++k) {
            state.q[k] = 0.01 * std::cos(0.7 * double(k));
            state.v[k] = 0.02 * std::sin(1.3 * double(k) + 0.2);
        }
        start.resize(kOscillatorPoints);
        start.assign(state);
    }
    // Coordinate k of the closed form at time t.
    double exact_q(std::size_t k, double t) const {
        return start.q[k] * std::cos(omega * t) + start.v[k] / omega * std::sin(omega * t);
    }
    double exact_v(std::size_t k, double t) const {
        return -start.q[k] * omega * std::sin(omega * t) + start.v[k] * std::cos(omega * t);
    }
    // The largest error of q against the closed form at the state's time, m.
    double error() const {
        double e = 0.0;
        for (std::size_t k = 0; k < state.q.size(); ++k) e = std::max(e, std::fabs(state.q[k] - exact_q(k, state.time)));
        return e;
    }
    // Runs `integrator` for `steps` steps of h; false if a step failed.
    bool run(mech::Integrator& integrator, double h, int steps) {
        for (int i = 0; i < steps; ++i)
            if (!integrator.step(dynamics, state, h)) return false;
        return true;
    }
    // The energy of the oscillators, 1/2 v^T M v + 1/2 omega^2 q^T M q, J.
    double energy() {
        const mech::Dynamics::Energies e = dynamics.energies(state);
        return e.kinetic + e.potential;
    }

    double omega;
    mech::Dynamics dynamics;
    mech::State state;
    mech::State start;
};

}  // namespace mechanics_test
