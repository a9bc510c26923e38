// SPDX-License-Identifier: Apache-2.0
#include "mechanics/stepper.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "base/error.h"

namespace enteron::mechanics {

namespace {

uint64_t elapsed_ns(std::chrono::steady_clock::time_point start) {
    return static_cast<uint64_t>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace

Stepper::Stepper(Dynamics& dynamics, RigidFrames& frames, const StepperSettings& settings, Logger logger,
                 std::pmr::memory_resource* memory)
    : dynamics_(dynamics),
      frames_(frames),
      settings_(settings),
      logger_(logger),
      integrator_(make_integrator(settings.integrator, dynamics.model(), memory)),
      state_(memory),
      start_(memory),
      guard_(settings.max_speed, settings.total_mass) {
    state_.resize(dynamics.model().control_points);
    start_.resize(dynamics.model().control_points);
}

// The step, stage by stage (stepper.h).
bool Stepper::step(double dt) {
    const auto start = std::chrono::steady_clock::now();
    // 1. substeps
    const std::size_t substeps = substeps_for(dt);
    // 2. keep
    keep_start();
    // 3. frames
    frames_.begin_step(state_.time, dt);
    // 4. commands
    const bool grasped = dynamics_.take_commands(state_, dt);
    // 5. begin
    dynamics_.begin_step(dt);
    // 6. prescribe: the velocities of points pinned to moving frames change the energy, and
    // so does a grasp taken or let go.
    if (dynamics_.prescribe(state_, dt) || grasped) guard_.set_reference(dynamics_.energies(state_));
    // 7. attempts
    std::size_t attempt = 0;
    bool accepted = false;
    for (;;) {
        dynamics_.begin_attempt();
        if (attempt > 0) dynamics_.prescribe(state_, dt);
        accepted = attempt_passes(dt, substeps << attempt);
        if (accepted || attempt == settings_.max_subdivisions) break;
        back_to_start();
        ++attempt;
        if (logger_.enabled())
            logger_.log(LogLevel::warning, "step at t = %g s rejected by the guard (%s); retrying with %zu substeps",
                        state_.time, guard_check_name(guard_.last_finding().check), substeps << attempt);
    }
    if (!accepted) {
        failure_ = failure_message(dt, substeps);
        back_to_start();
    }
    // 8. end
    dynamics_.end_step(accepted);
    frames_.end_step(accepted);
    counters_.steps += accepted ? 1 : 0;
    counters_.last_step_ns = elapsed_ns(start);
    return accepted;
}

std::size_t Stepper::substeps_for(double dt) const {
    if (!std::isfinite(dt) || !(dt > 0.0)) {
        char message[128];
        std::snprintf(message, sizeof message, "dt_s must be finite and > 0, got %g", dt);
        throw Error(ErrorCode::invalid_argument, message);
    }
    const double longest = longest_substep();
    const double needed = std::ceil(dt / longest * (1.0 - 1e-12));
    if (!(needed <= static_cast<double>(settings_.max_substeps))) {
        char message[256];
        std::snprintf(message, sizeof message,
                      "dt_s = %g needs %g substeps of at most %g s, more than max_substeps (%zu)", dt, needed,
                      longest, settings_.max_substeps);
        throw Error(ErrorCode::invalid_argument, message);
    }
    return std::max<std::size_t>(1, static_cast<std::size_t>(needed));
}

// The rollback contract (stepper.h): the effects' part is their begin_attempt.
void Stepper::keep_start() {
    start_.assign(state_);
    integrator_->save_history();
}

void Stepper::back_to_start() {
    state_.assign(start_);
    integrator_->restore_history();
}

bool Stepper::attempt_passes(double dt, std::size_t substeps) {
    const double h = dt / static_cast<double>(substeps);
    const double start_time = state_.time;
    for (std::size_t i = 0; i < substeps; ++i) {
        counters_.substeps += 1;
        const bool solved = integrator_->step(dynamics_, state_, h);
        if (!guard_.substep_passes(solved, state_)) return false;
    }
    state_.time = start_time + dt;  // no drift from summing substeps
    return guard_.step_passes(state_, dynamics_);
}

double Stepper::longest_substep() const { return std::min(settings_.timestep, explicit_substep_limit_); }

void Stepper::effects_changed() {
    dynamics_.finalize();
    explicit_substep_limit_ = dynamics_.explicit_substep_limit(integrator_->stability_interval());
    guard_.set_reference(dynamics_.energies(state_));
}

void Stepper::energy_changed() { guard_.set_reference(dynamics_.energies(state_)); }

void Stepper::state_set_from_outside() { integrator_->restart(); }

}  // namespace enteron::mechanics
