// SPDX-License-Identifier: Apache-2.0
#include "mechanics/dynamics.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "base/error.h"
#include "base/state_io.h"
#include "mechanics/axial_blocks.h"

namespace enteron::mechanics {

namespace {
// Power iteration gives the top eigenvalue from below; this margin covers its error.
constexpr double kEigenvalueMargin = 1.2;
constexpr int kPowerIterations = 200;

uint64_t now_ns() {
    return static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                     std::chrono::steady_clock::now().time_since_epoch())
                                     .count());
}
}  // namespace

Dynamics::Dynamics(const AxisModel& model, std::pmr::memory_resource* memory)
    : model_(model),
      memory_(memory),
      effects_(memory),
      driven_(memory),
      shared_loads_(memory),
      mass_(memory),
      mass_products_(memory),
      mass_factor_(memory),
      clamped_mass_factor_(memory),
      constant_system_(memory),
      border_(memory),
      scratch_(memory),
      one_effect_force_(memory) {
    const std::size_t n = model.control_points;
    mass_.resize(n);
    add_mass_matrix(model, mass_);
    mass_products_.assign(mass_);
    mass_factor_.resize(n);
    constant_system_.resize(3 * n);
    scratch_.assign(3 * n, 0.0);
    one_effect_force_.assign(3 * n, 0.0);
}

void Dynamics::add_owned_effect(Owned<Effect> effect) {
    enabled_[static_cast<std::size_t>(effect->id())] = true;
    effects_.push_back(std::move(effect));
}

void Dynamics::add_pins(Owned<PinnedPoints> pins) {
    enabled_[static_cast<std::size_t>(EffectId::pinned)] = true;
    pinned_ = std::move(pins);
}

void Dynamics::add_clamps(Owned<ClampedEnds> clamps) { clamped_ = std::move(clamps); }

void Dynamics::add_shared_loads(SharedLoads* loads, EffectId owner) { shared_loads_.emplace_back(loads, owner); }

void Dynamics::finalize() {
    mass_factor_.assign(mass_);
    if (pinned_) pinned_->constrain(mass_factor_);
    if (!mass_factor_.factor()) throw Error(ErrorCode::internal, "the mass matrix is not positive definite");
    if (clamped_) {
        clamped_mass_factor_.resize(coordinates());
        factor_clamped_mass();
    }

    const std::size_t n = model_.control_points;
    numerics::ScalarBandMatrix stiffness(memory_), damping(memory_);
    stiffness.resize(n);
    damping.resize(n);
    for (const Owned<Effect>& effect : effects_) {
        effect->add_stiffness_bound(stiffness);
        effect->add_damping_bound(damping);
    }
    if (pinned_) {
        pinned_->constrain(stiffness);
        pinned_->constrain(damping);
    }
    std::size_t bodies = 0;
    for (const DrivenEffect* effect : driven_) bodies += effect->border_bodies();
    border_.reserve(bodies, coordinates());
    max_frequency_ = std::sqrt(kEigenvalueMargin * largest_eigenvalue(stiffness));
    max_damping_rate_ = kEigenvalueMargin * largest_eigenvalue(damping);
    constant_system_h_ = -1.0;
}

double Dynamics::largest_eigenvalue(const numerics::ScalarBandMatrix& bound) const {
    // Power iteration on M^-1 B, started from the most oscillating vector (the top modes of
    // a chain alternate in sign), with the Rayleigh quotient x^T B x / x^T M x as estimate.
    const std::size_t n = model_.control_points;
    std::pmr::vector<double> x(n, 0.0, memory_), y(n, 0.0, memory_), mx(n, 0.0, memory_);
    for (std::size_t i = 0; i < n; ++i) x[i] = (i % 2 == 0 ? 1.0 : -1.0) * (1.0 + 0.3 * std::sin(1.0 + i));
    double estimate = 0.0;
    for (int iteration = 0; iteration < kPowerIterations; ++iteration) {
        bound.multiply(x.data(), y.data());
        mass_.multiply(x.data(), mx.data());
        double xbx = 0.0, xmx = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            xbx += x[i] * y[i];
            xmx += x[i] * mx[i];
        }
        estimate = xmx > 0.0 ? xbx / xmx : 0.0;
        mass_factor_.solve(y.data());
        double norm = 0.0;
        for (double v : y) norm = std::max(norm, std::fabs(v));
        if (!(norm > 0.0)) return 0.0;
        for (std::size_t i = 0; i < n; ++i) x[i] = y[i] / norm;
    }
    return estimate;
}

double Dynamics::explicit_substep_limit(double stability_interval) const {
    constexpr double kSafety = 0.9;
    const double rate = max_frequency_ + max_damping_rate_;
    if (!(rate > 0.0)) return std::numeric_limits<double>::infinity();
    return kSafety * stability_interval / rate;
}

void Dynamics::forces(const State& state, double* force, const Linearization* lin) {
    const std::size_t m = coordinates();
    std::fill(force, force + m, 0.0);
    if (lin != nullptr) std::fill(lin->stiffness_times_velocity, lin->stiffness_times_velocity + m, 0.0);
    auto run = [&](Effect& effect) {
        const uint64_t start = now_ns();
        effect.evaluate(state, force, lin);
        EffectCounters& counter = counters_[static_cast<std::size_t>(effect.id())];
        counter.calls += 1;
        counter.total_time_ns += now_ns() - start;
    };
    // The axial laws (stretch, damping) share their blocks (axial_blocks.h); without them
    // the blocks cost nothing.
    const bool axial_laws = has_effect(EffectId::stretch) || has_effect(EffectId::damping);
    AxialBlocks* axial = lin != nullptr && axial_laws ? lin->axial : nullptr;
    if (axial != nullptr) axial->clear();
    for (const auto& [loads, owner] : shared_loads_) loads->clear();
    for (Owned<Effect>& effect : effects_) run(*effect);
    for (const auto& [loads, owner] : shared_loads_) {
        const uint64_t start = now_ns();
        loads->apply(force, lin);
        counters_[static_cast<std::size_t>(owner)].total_time_ns += now_ns() - start;
    }
    // The blocks reach the system before the pins make their rows identity. Their time is
    // the stretch's (or the damper's, without stretch): per-effect times stay whole.
    if (axial != nullptr) {
        const uint64_t start = now_ns();
        axial->add_to(*lin->system);
        const EffectId owner = has_effect(EffectId::stretch) ? EffectId::stretch : EffectId::damping;
        counters_[static_cast<std::size_t>(owner)].total_time_ns += now_ns() - start;
    }
    if (pinned_) run(*pinned_);
}

void Dynamics::factor_clamped_mass() {
    // The clamps mix x, y and z: M over the 3n coordinates, with the same constraints.
    clamped_mass_factor_.set_zero();
    add_per_coordinate(mass_, 1.0, clamped_mass_factor_);
    if (pinned_) pinned_->constrain(clamped_mass_factor_);
    clamped_->reduce(clamped_mass_factor_);
    if (!clamped_mass_factor_.factor())
        throw Error(ErrorCode::internal, "the clamped mass matrix is not positive definite");
    clamped_mass_stale_ = false;
}

bool Dynamics::prescribe(State& state, double dt) {
    if (!pinned_) return false;
    const bool moving = pinned_->prescribe(state, dt);
    // A turning clamp changes control point 1's velocity: the stability guard's reference
    // must be taken again, as for a moving pin. Only the explicit integrators use the
    // clamped mass matrix (solve_mass): it is factored there, on first use.
    const bool turned = clamped_ && clamped_->prescribe(state, dt, pinned_->speed_limit());
    if (turned) clamped_mass_stale_ = true;
    return moving || turned;
}

void Dynamics::acceleration(const State& state, double* acceleration) {
    forces(state, acceleration, nullptr);
    solve_mass(acceleration);
}

void Dynamics::solve_mass(double* x) {
    if (!clamped_) return mass_factor_.solve(x, 3, 3);
    if (clamped_mass_stale_) factor_clamped_mass();
    clamped_->reduce_rhs(x, nullptr);
    clamped_mass_factor_.solve(x);
    clamped_->expand(x);
}

bool Dynamics::solve_velocity_change(SystemMatrix& system, double* rhs, const State& state,
                                     BorderedSystem* border) const {
    if (pinned_) pinned_->zero_rows(rhs);
    if (clamped_) {
        clamped_->reduce(system);
        clamped_->reduce_rhs(rhs, state.v.data());
    }
    if (!system.factor()) return false;
    system.solve(rhs);
    if (border != nullptr) border->solve(system, rhs);  // the bodies of effects that have them (tools' proxies)
    if (clamped_) clamped_->expand(rhs);
    return true;
}

const SystemMatrix& Dynamics::constant_system(double h) {
    if (h == constant_system_h_) return constant_system_;
    constant_system_.set_zero();
    add_per_coordinate(mass_, 1.0, constant_system_);
    for (const Owned<Effect>& effect : effects_) effect->add_constant_linearization(h, constant_system_);
    constant_system_h_ = h;
    return constant_system_;
}

double Dynamics::kinetic_energy(const State& state) const {
    mass_products_.multiply(state.v.data(), scratch_.data());
    double energy = 0.0;
    for (std::size_t k = 0; k < scratch_.size(); ++k) energy += 0.5 * state.v[k] * scratch_[k];
    return energy;
}

Dynamics::Energies Dynamics::energies(const State& state) const {
    Energies energies;
    energies.kinetic = kinetic_energy(state);
    for (const Owned<Effect>& effect : effects_) {
        const double energy = effect->potential_energy(state);
        energies.potential += energy;
        if (effect->id() != EffectId::gravity) energies.deformation += energy;
    }
    return energies;
}

bool Dynamics::take_commands(const State& state, double dt) {
    bool energy_changed = false;
    for (DrivenEffect* effect : driven_) energy_changed |= effect->take_commands(state, dt);
    return energy_changed;
}

void Dynamics::begin_step(double dt) {
    for (Owned<Effect>& effect : effects_) effect->begin_step(dt);
    if (pinned_) pinned_->begin_step(dt);
}

void Dynamics::evaluation_used(double duration, const State* after) {
    for (DrivenEffect* effect : driven_) effect->evaluation_used(duration, after);
}

void Dynamics::begin_attempt() {
    for (Owned<Effect>& effect : effects_) effect->begin_attempt();
    if (pinned_) pinned_->begin_attempt();
}

void Dynamics::end_step(bool accepted) {
    for (DrivenEffect* effect : driven_) effect->end_step(accepted);
}

Dynamics::Culprit Dynamics::strongest_force_at(const State& state, std::size_t control_point) {
    Culprit strongest;
    double* force = one_effect_force_.data();
    for (Owned<Effect>& effect : effects_) {
        std::fill(one_effect_force_.begin(), one_effect_force_.end(), 0.0);
        // The contact effects put their forces into the shared loads.
        for (const auto& [loads, owner] : shared_loads_) loads->clear();
        effect->evaluate(state, force, nullptr);
        for (const auto& [loads, owner] : shared_loads_) loads->apply(force, nullptr);
        const double* f = force + 3 * control_point;
        const double magnitude = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        // NaN compares false: a non-finite force wins at once.
        if (!strongest.found || !(magnitude <= strongest.amount)) strongest = {true, effect->id(), magnitude};
    }
    return strongest;
}

Dynamics::Culprit Dynamics::largest_energy_gain(const State& before, const State& after) const {
    Culprit largest;
    for (const Owned<Effect>& effect : effects_) {
        const double gain = effect->potential_energy(after) - effect->potential_energy(before);
        if (!(gain <= 0.0) && (!largest.found || !(gain <= largest.amount))) largest = {true, effect->id(), gain};
    }
    return largest;
}

ContactSummary Dynamics::contacts() const {
    ContactSummary summary;
    for (const Owned<Effect>& effect : effects_) effect->add_contacts(summary);
    return summary;
}

StepWork Dynamics::work() const {
    StepWork work;
    for (const Owned<Effect>& effect : effects_) effect->add_work(work);
    return work;
}

double Dynamics::external_work_bound() const {
    double work = 0.0;
    for (const Owned<Effect>& effect : effects_) work += effect->external_work_bound();
    if (pinned_) work += pinned_->external_work_bound();
    return work;
}

void Dynamics::save_state(StateWriter& out) const {
    // Version 2: the clamped ends' attachments follow the counters. Version 3: the effects'
    // wall-clock times are not saved (two identical runs save identical images).
    out.begin_section("dynamics", 3);
    for (const EffectCounters& counter : counters_) out.u64(counter.calls);
    if (clamped_) clamped_->save_attachments(out);
    else out.u32(0);
    out.end_section();
    for (const Owned<Effect>& effect : effects_) effect->save_state(out);
    if (pinned_) pinned_->save_state(out);
}

void Dynamics::restore_state(StateReader& in, const RigidFrames& frames) {
    const uint32_t version = in.begin_section("dynamics", 3);
    std::array<uint64_t, kEffectCount> calls{};
    for (uint64_t& count : calls) {
        count = in.u64("effect calls");
        if (version < 3) in.u64("effect time");  // a wall-clock figure: dropped
    }
    // Version 1 (before clamped ends could follow frames): they stay as they are.
    if (version >= 2) {
        if (clamped_) clamped_->restore_attachments(in, frames);
        else if (in.count("clamped ends", 0) != 0) in.fail("the saved scene clamps ends, this one does not");
    }
    in.end_section();
    for (Owned<Effect>& effect : effects_) effect->restore_state(in);
    if (pinned_) pinned_->restore_state(in, model_.control_points);
    // The calls are the simulation's work; the times stay this process's.
    if (!in.checking())
        for (std::size_t i = 0; i < calls.size(); ++i) counters_[i].calls = calls[i];
}

void Dynamics::add_layout(Fingerprint& fingerprint) const {
    for (const Owned<Effect>& effect : effects_) fingerprint.add(static_cast<uint64_t>(effect->id()));
    fingerprint.add(uint64_t{pinned_ != nullptr});
}

}  // namespace enteron::mechanics
