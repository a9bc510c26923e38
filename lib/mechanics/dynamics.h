// SPDX-License-Identifier: Apache-2.0
// The equations of motion of the axis, M a = F(q, v), with M the constant banded mass
// matrix (factored once) and F the sum of the effects the scene names. Integrators ask it
// for forces, accelerations, linearisations and energies; it times every effect.
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <memory_resource>
#include <vector>

#include "base/memory.h"
#include "mechanics/axis_model.h"
#include "mechanics/bordered_system.h"
#include "mechanics/clamped_ends.h"
#include "mechanics/driven_effect.h"
#include "mechanics/effect.h"
#include "mechanics/per_coordinate_matrix.h"
#include "mechanics/pinned_points.h"

namespace enteron::mechanics {

// What one effect cost so far.
struct EffectCounters {
    uint64_t calls = 0;
    uint64_t total_time_ns = 0;
};

class Dynamics {
public:
    Dynamics(const AxisModel& model, std::pmr::memory_resource* memory);

    // Adds an effect (a driven one, driven_effect.h, gets its hooks too), or the pins (which
    // always run last); call finalize() once all are in, and again after adding an effect
    // later. Returns the effect added, for the assembly to keep (the dynamics owns it).
    template <class T>
    T& add_effect(Owned<T> effect) {
        T& added = *effect;
        if constexpr (std::is_base_of_v<DrivenEffect, T>) driven_.push_back(&added);
        add_owned_effect(std::move(effect));
        return added;
    }
    void add_pins(Owned<PinnedPoints> pins);
    // Clamps ends (clamped_ends.h): every linear solve below then keeps their tangents. The
    // end points themselves must be among the pins.
    void add_clamps(Owned<ClampedEnds> clamps);
    // Loads that effects share (effect.h): forces() clears them before the effects and
    // applies them after, their time counted as `owner`'s. Not owned: they must outlive
    // every call to forces().
    void add_shared_loads(SharedLoads* loads, EffectId owner);
    // The pins, or null before the first.
    PinnedPoints* pins() { return pinned_.get(); }
    // Factors the mass matrix (with the pins) and bounds the explicit stable substep.
    void finalize();

    const AxisModel& model() const { return model_; }
    std::size_t coordinates() const { return 3 * model_.control_points; }
    bool has_effect(EffectId id) const { return enabled_[static_cast<std::size_t>(id)]; }
    const EffectCounters& counters(EffectId id) const { return counters_[static_cast<std::size_t>(id)]; }

    // force = F(state); with lin, also the linearisation (see effect.h), the shared axial
    // blocks (lin->axial) cleared first and added to the system before the pins. Times each effect.
    void forces(const State& state, double* force, const Linearization* lin);
    // acceleration = M^-1 F(state) (with the clamps' constraints).
    void acceleration(const State& state, double* acceleration);
    // out = M x for a 3n vector (the unconstrained mass matrix).
    void multiply_mass(const double* x, double* out) const { mass_products_.multiply(x, out); }
    // x = M^-1 x for a 3n vector (with the clamps' constraints). Factors the clamped mass
    // matrix again first if a clamp turned since (allocates nothing).
    void solve_mass(double* x);
    // Solves system dv = rhs in place for the velocity change dv of the state `state`: the
    // implicit integrators' system, assembled by forces() with a linearisation. The pinned
    // rows of rhs are zeroed (dv = 0 there), the clamps' constraints hold for v + dv. Factors
    // (and, with clamps, changes) `system`. False if it is not positive definite.
    // With `border` (border()), its bodies are solved with the bowel (bordered_system.h).
    bool solve_velocity_change(SystemMatrix& system, double* rhs, const State& state,
                               BorderedSystem* border = nullptr) const;

    // Builds M + sum of the constant parts of h C + h^2 H, pins applied: the start of the
    // implicit system for substep h. Cached: rebuilt only when h changes.
    const SystemMatrix& constant_system(double h);

    // The border of the implicit system (bordered_system.h), sized by finalize() for the
    // bodies the effects may add; null with clamped ends, whose reduced system the border
    // does not know (the tools' proxies then stay put through each substep).
    BorderedSystem* border() { return clamped_ ? nullptr : &border_; }
    // Tells the driven effects how the integrator used their last evaluation
    // (DrivenEffect::evaluation_used).
    void evaluation_used(double duration, const State* after);

    // The effects' step hooks (effect.h, driven_effect.h), each in the order the effects were
    // added, the pins last; the stepper (stepper.h) calls them in the order of a step.
    // take_commands returns true if a driven effect changed the energy it stores.
    bool take_commands(const State& state, double dt);
    void begin_step(double dt);
    void begin_attempt();
    void end_step(bool accepted);
    // Before each attempt: the velocities of the points pinned to moving frames
    // (pinned_points.h), then the turn of the clamped ends attached to frames
    // (clamped_ends.h; the clamped mass matrix is then stale, factored again by the next
    // solve_mass). True if one of those velocities is not zero or a clamp changed one.
    bool prescribe(State& state, double dt);
    // The clamps, or null.
    ClampedEnds* clamps() { return clamped_.get(); }

    // Contacts of the effects' last evaluations.
    ContactSummary contacts() const;

    // Save and restore (base/state_io.h): the effect counters in a section of their own,
    // then each effect's section (Effect::save_state), the pins' last. restore_state reads
    // them back in the same order, assigning only when !in.checking().
    void save_state(StateWriter& out) const;
    // `frames` are those the clamped ends may follow.
    void restore_state(StateReader& in, const RigidFrames& frames);
    // Adds the effects in the order they run (the order of their sections) to a fingerprint.
    void add_layout(Fingerprint& fingerprint) const;
    // Work the effects driven from outside may do in the current step (effect.h), J.
    double external_work_bound() const;

    struct Energies {
        double kinetic = 0.0;      // J
        double potential = 0.0;    // J, every effect's
        double deformation = 0.0;  // J, the part stored in deformation and contacts (all but gravity), >= 0
    };
    Energies energies(const State& state) const;
    double kinetic_energy(const State& state) const;

    // For the guard's report of a failed step (not on the stepping path: it evaluates every
    // effect again, alone, without timing it). The effect whose force on control point
    // `control_point` is the largest in `state`, and that force's magnitude (N); and the
    // effect whose potential energy grew the most from `before` to `after`, and by how much
    // (J). `found` is false when the scene has no effect (or none gained energy).
    struct Culprit {
        bool found = false;
        EffectId effect = EffectId::stretch;
        double amount = 0.0;
    };
    Culprit strongest_force_at(const State& state, std::size_t control_point);
    Culprit largest_energy_gain(const State& before, const State& after) const;

    // The longest substep an explicit method with stability interval [-beta, 0] on the
    // imaginary / real axes may take, from bounds on the highest frequency omega and the
    // strongest damping rate gamma: h <= safety * beta / (omega + gamma). Infinite when
    // nothing is stiff (gravity only).
    double explicit_substep_limit(double stability_interval) const;

private:
    void add_owned_effect(Owned<Effect> effect);
    double largest_eigenvalue(const numerics::ScalarBandMatrix& bound) const;
    // M over the 3n coordinates with the pins and the clamps' reduction, factored.
    void factor_clamped_mass();

    AxisModel model_;
    std::pmr::memory_resource* memory_;
    std::pmr::vector<Owned<Effect>> effects_;
    std::pmr::vector<DrivenEffect*> driven_;  // those of effects_ driven from outside
    Owned<PinnedPoints> pinned_;
    Owned<ClampedEnds> clamped_;
    std::pmr::vector<std::pair<SharedLoads*, EffectId>> shared_loads_;
    std::array<bool, kEffectCount> enabled_{};
    std::array<EffectCounters, kEffectCount> counters_{};
    numerics::ScalarBandMatrix mass_;          // M per coordinate, unfactored
    PerCoordinateMatrix mass_products_;      // M again, for M v
    numerics::ScalarBandMatrix mass_factor_;   // M with pins, Cholesky factor
    SystemMatrix clamped_mass_factor_;         // with clamps: M over the 3n coordinates, pinned, clamped, factored
    bool clamped_mass_stale_ = false;          // a clamp turned since clamped_mass_factor_ was factored
    SystemMatrix constant_system_;
    BorderedSystem border_;
    double constant_system_h_ = -1.0;
    double max_frequency_ = 0.0;      // rad/s, bound on sqrt(eig(M^-1 K))
    double max_damping_rate_ = 0.0;   // 1/s, bound on eig(M^-1 C)
    mutable std::pmr::vector<double> scratch_;
    std::pmr::vector<double> one_effect_force_;  // strongest_force_at's, sized once
};

}  // namespace enteron::mechanics
