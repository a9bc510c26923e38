// SPDX-License-Identifier: Apache-2.0
#include "mechanics/bdf2.h"

#include <algorithm>

#include "base/state_io.h"

namespace enteron::mechanics {

void Bdf2::History::assign(const History& other) {
    std::copy(other.q.begin(), other.q.end(), q.begin());
    std::copy(other.v.begin(), other.v.end(), v.begin());
    h = other.h;
    valid = other.valid;
    contacts = other.contacts;
    contacts_kept = other.contacts_kept;
}

Bdf2::Bdf2(const AxisModel& model, std::pmr::memory_resource* memory)
    : work_(model, memory),
      predicted_(memory),
      velocity_difference_(3 * model.control_points, 0.0, memory),
      history_momentum_(3 * model.control_points, 0.0, memory),
      history_(3 * model.control_points, memory),
      saved_history_(3 * model.control_points, memory) {
    predicted_.resize(model.control_points);
}

void Bdf2::save_history() {
    saved_history_.assign(history_);
    retrying_ = false;
}

void Bdf2::restore_history() {
    history_.assign(saved_history_);
    retrying_ = true;
}

// Version 2 adds the contacts after the velocities; a version 1 history does not know them,
// so its next substep is taken at first order.
void Bdf2::save_state(StateWriter& out) const {
    out.begin_section("bdf2", 2);
    out.u8(history_.valid ? 1 : 0);
    out.f64(history_.h);
    out.f64s(history_.q.data(), history_.q.size());
    out.f64s(history_.v.data(), history_.v.size());
    out.u32(history_.contacts);
    out.u8(history_.contacts_kept ? 1 : 0);
    out.end_section();
}

void Bdf2::restore_state(StateReader& in) {
    const uint32_t version = in.begin_section("bdf2", 2);
    const bool valid = in.flag("history valid");
    const double h = in.f64("previous substep");
    if (valid && !(h > 0.0)) in.fail("the previous substep is not positive");
    in.f64s("previous positions", history_.q.size(), in.checking() ? nullptr : history_.q.data());
    in.f64s("previous velocities", history_.v.size(), in.checking() ? nullptr : history_.v.data());
    const uint32_t contacts = version >= 2 ? in.u32("previous contacts") : 0;
    const bool contacts_kept = version >= 2 ? in.flag("contacts kept") : false;
    in.end_section();
    if (in.checking()) return;
    history_.valid = valid;
    history_.h = h;
    history_.contacts = contacts;
    history_.contacts_kept = contacts_kept;
}

bool Bdf2::second_order_next(double h) const {
    return history_.valid && !retrying_ && history_.contacts_kept && h <= kMaxStepRatio * history_.h;
}

bool Bdf2::step(Dynamics& dynamics, State& state, double h) {
    bool solved;
    if (second_order_next(h)) {
        solved = second_order_step(dynamics, state, h, h / history_.h);
    } else {
        std::copy(state.q.begin(), state.q.end(), history_.q.begin());
        std::copy(state.v.begin(), state.v.end(), history_.v.begin());
        solved = implicit_euler_step(dynamics, state, h, work_);
    }
    if (!solved) return false;
    const uint32_t contacts = dynamics.contacts().count;
    history_.contacts_kept = contacts == history_.contacts;
    history_.contacts = contacts;
    history_.h = h;
    history_.valid = true;
    return true;
}

bool Bdf2::second_order_step(Dynamics& dynamics, State& state, double h, double w) {
    const std::size_t m = work_.rhs.size();
    double* rhs = work_.rhs.data();
    const double a = w * w / (1.0 + 2.0 * w);
    const double beta = h * (1.0 + w) / (1.0 + 2.0 * w);

    // The predictor q* = q_n + a (q_n - q_{n-1}) + beta v_n, taken at the substep's end.
    for (std::size_t k = 0; k < m; ++k) {
        predicted_.q[k] = state.q[k] + a * (state.q[k] - history_.q[k]) + beta * state.v[k];
        predicted_.v[k] = state.v[k];
    }
    predicted_.time = state.time + h;

    // (M + beta C + beta^2 H) dv = beta F(q*, v_n) + a M (v_n - v_{n-1}).
    work_.system.assign(dynamics.constant_system(beta));
    Linearization lin{&work_.system, beta, work_.stiffness_times_velocity.data(), &work_.axial};
    dynamics.forces(predicted_, rhs, &lin);
    for (std::size_t k = 0; k < m; ++k) velocity_difference_[k] = state.v[k] - history_.v[k];
    dynamics.multiply_mass(velocity_difference_.data(), history_momentum_.data());
    for (std::size_t k = 0; k < m; ++k) rhs[k] = beta * rhs[k] + a * history_momentum_[k];
    if (!dynamics.solve_velocity_change(work_.system, rhs, state)) return false;

    // The history becomes this substep's start; then q_{n+1} = q* + beta dv, v_{n+1} = v_n + dv.
    for (std::size_t k = 0; k < m; ++k) {
        history_.q[k] = state.q[k];
        history_.v[k] = state.v[k];
        state.v[k] += rhs[k];
        state.q[k] = predicted_.q[k] + beta * rhs[k];
    }
    state.time += h;
    // The tools report the linearised force at the substep's end over the substep.
    dynamics.evaluation_used(h, &state);
    return true;
}

}  // namespace enteron::mechanics
