#include "mechanics/bdf2.h"

#include <algorithm>

#include "base/state_io.h"

namespace enteron::mechanics {

void Bdf2::History::assign(const History& other) {
    std::copy(other.q.begin(), other.q.end(), q.begin());
    std::copy(other.v.begin(), other.v.end(), v.begin());
    h = other.h;
    valid = other.valid;
}

Bdf2::Bdf2(const AxisModel& model, std::pmr::memory_resource* memory)
    : system_(memory),
      axial_(model, memory),
      predicted_(memory),
      rhs_(3 * model.control_points, 0.0, memory),
      velocity_difference_(3 * model.control_points, 0.0, memory),
      history_momentum_(3 * model.control_points, 0.0, memory),
      stiffness_times_velocity_(3 * model.control_points, 0.0, memory),
      history_(3 * model.control_points, memory),
      saved_history_(3 * model.control_points, memory) {
    system_.resize(3 * model.control_points);
    predicted_.resize(model.control_points);
}

void Bdf2::save_history() { saved_history_.assign(history_); }

void Bdf2::restore_history() { history_.assign(saved_history_); }

void Bdf2::save_state(StateWriter& out) const {
    out.begin_section("bdf2", 1);
    out.u8(history_.valid ? 1 : 0);
    out.f64(history_.h);
    out.f64s(history_.q.data(), history_.q.size());
    out.f64s(history_.v.data(), history_.v.size());
    out.end_section();
}

void Bdf2::restore_state(StateReader& in) {
    in.begin_section("bdf2", 1);
    const bool valid = in.flag("history valid");
    const double h = in.f64("previous substep");
    if (valid && !(h > 0.0)) in.fail("the previous substep is not positive");
    in.f64s("previous positions", history_.q.size(), in.checking() ? nullptr : history_.q.data());
    in.f64s("previous velocities", history_.v.size(), in.checking() ? nullptr : history_.v.data());
    in.end_section();
    if (in.checking()) return;
    history_.valid = valid;
    history_.h = h;
}

bool Bdf2::step(Dynamics& dynamics, State& state, double h) {
    const std::size_t m = rhs_.size();
    // w = h_n / h_{n-1}; no history: w = 0, one implicit Euler step.
    const double w = history_.valid ? h / history_.h : 0.0;
    const double a = w * w / (1.0 + 2.0 * w);
    const double beta = h * (1.0 + w) / (1.0 + 2.0 * w);

    // The predictor q* = q_n + a (q_n - q_{n-1}) + beta v_n, taken at the substep's end.
    for (std::size_t k = 0; k < m; ++k) {
        const double q_change = history_.valid ? state.q[k] - history_.q[k] : 0.0;
        predicted_.q[k] = state.q[k] + a * q_change + beta * state.v[k];
        predicted_.v[k] = state.v[k];
    }
    predicted_.time = state.time + h;

    // (M + beta C + beta^2 H) dv = beta F(q*, v_n) + a M (v_n - v_{n-1}).
    system_.assign(dynamics.constant_system(beta));
    Linearization lin{&system_, beta, stiffness_times_velocity_.data(), &axial_};
    dynamics.forces(predicted_, rhs_.data(), &lin);
    if (a != 0.0) {
        for (std::size_t k = 0; k < m; ++k) velocity_difference_[k] = state.v[k] - history_.v[k];
        dynamics.multiply_mass(velocity_difference_.data(), history_momentum_.data());
        for (std::size_t k = 0; k < m; ++k) rhs_[k] = beta * rhs_[k] + a * history_momentum_[k];
    } else {
        for (std::size_t k = 0; k < m; ++k) rhs_[k] *= beta;
    }
    if (!dynamics.solve_velocity_change(system_, rhs_.data(), state)) return false;

    // The history becomes this substep's start; then q_{n+1} = q* + beta dv, v_{n+1} = v_n + dv.
    for (std::size_t k = 0; k < m; ++k) {
        history_.q[k] = state.q[k];
        history_.v[k] = state.v[k];
        state.v[k] += rhs_[k];
        state.q[k] = predicted_.q[k] + beta * rhs_[k];
    }
    history_.h = h;
    history_.valid = true;
    state.time += h;
    // The tools report the linearised force at the substep's end over the substep.
    dynamics.evaluation_used(h, &state);
    return true;
}

}  // namespace enteron::mechanics
