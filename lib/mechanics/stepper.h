// SPDX-License-Identifier: Apache-2.0
// One step of the axis as a transaction: it advances the state by dt, or leaves it exactly as
// it was. stepper.cpp reads top to bottom as the sequence of the step's stages (as MuJoCo's
// mj_step and Box2D's b2World_Step do), one call each:
//
//   1. substeps    dt split into equal substeps, none longer than the solver's timestep or
//                  the explicit integrators' stable limit (a bad dt is refused here)
//   2. keep        the step's start, for a rollback (the contract below)
//   3. frames      the obstacles' frames start towards the poses set since the last step
//   4. commands    the effects driven from outside (the tools) take their commands: poses,
//                  grasps, releases (driven_effect.h)
//   5. begin       every effect learns the step's length
//   6. prescribe   the points pinned to moving frames and the clamped ends attached to them
//                  take their velocities; if they or a grasp changed the energy, the guard
//                  measures it again
//   7. attempts    at most 1 + max_subdivisions, each with twice the substeps of the last:
//                  every effect starts the attempt from the step's start, a retry prescribes
//                  again, then the substeps (the integrator, the guard after each) and the
//                  guard's end-of-step checks (speed, energy)
//   8. end         accepted: the driven effects write their outputs, the frames rest at
//                  their targets; every attempt rejected: back to the step's start, the
//                  driven effects and the frames told so, and step() returns false with
//                  failure() naming what went wrong
//
// The rollback contract: what an attempt changes and a retry (or a failed step) must find
// again as the step began is declared once, in keep_start() and back_to_start():
//   - the axis state q, v, t (kept in start_);
//   - the integrator's history, a multistep method's earlier substeps (Integrator::save_history);
//   - what each effect changed during the attempt: the tools' proxies and the sums of their
//     impulses, the largest power of the moving frames (Effect::begin_attempt, called before
//     every attempt).
// Nothing else moves within an attempt: the frames move on only when the step is accepted,
// the guard's reference only when an attempt passes, and the prescribed velocities are set
// again from the restored state. The counters (substeps, rollbacks, the effects' time) keep
// the work of rejected attempts. Anything new that an attempt changes joins that list.
//
// Threads: the driving thread only; step() allocates nothing unless a step fails.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <string>

#include "base/logger.h"
#include "base/memory.h"
#include "mechanics/dynamics.h"
#include "mechanics/integrator.h"
#include "mechanics/rigid_frames.h"
#include "mechanics/stability_guard.h"
#include "mechanics/state.h"

namespace enteron {
class StateWriter;
class StateReader;
}  // namespace enteron

namespace enteron::mechanics {

struct StepperSettings {
    IntegratorKind integrator = IntegratorKind::implicit_euler;
    double timestep = 1e-3;            // s, the longest substep
    std::size_t max_substeps = 1000;   // in one step
    std::size_t max_subdivisions = 4;  // retries of a rejected step, each with twice the substeps
    double max_speed = 50.0;           // m/s, the guard's bound on every control point
    double total_mass = 1.8;           // kg, of the bowel: the floor of the guard's energy allowance
};

// What the steps did since the scene was made (published in ent_stats; rollbacks are the
// guard's).
struct StepCounters {
    uint64_t steps = 0;         // accepted
    uint64_t substeps = 0;      // taken, those of rejected attempts too
    uint64_t last_step_ns = 0;  // wall time of the last step, ns
};

class Stepper {
public:
    // Steps `dynamics` (its effects added by the caller, who calls effects_changed() once
    // they are in) with its obstacles' `frames`; both must outlive the stepper. The state
    // starts with dynamics' control points at the origin, at rest, at t = 0: the caller
    // places them (state()) before the first step.
    Stepper(Dynamics& dynamics, RigidFrames& frames, const StepperSettings& settings, Logger logger,
            std::pmr::memory_resource* memory);

    Stepper(const Stepper&) = delete;
    Stepper& operator=(const Stepper&) = delete;

    // Advances the state by dt seconds (the stages above). True if a step passed the guard;
    // false with the state exactly as before when every attempt was rejected (failure() says
    // why). Throws Error(invalid_argument), with nothing changed, for a dt that is not finite
    // and positive or that needs more than max_substeps.
    bool step(double dt);
    // Why the last failed step failed: the check, by how much, where, and the likeliest
    // culprit among the effects (empty before any failure).
    const std::string& failure() const { return failure_; }

    // Between steps: the state, for the changes made from outside (a pin stops its point)
    // and for publishing.
    State& state() { return state_; }
    const State& state() const { return state_; }

    // Between steps, after the set of effects or their bounds changed (an effect added, an
    // obstacle's friction): the dynamics finalized again, the explicit substep limit and the
    // guard's reference energy measured again.
    void effects_changed();
    // Between steps, after a change of the stored energy alone (gravity): the guard's reference.
    void energy_changed();
    // Between steps, after the state was set from outside (a pinned point stopped): a
    // multistep integrator starts again from the new state (Integrator::restart).
    void state_set_from_outside();

    // The longest substep a step takes, s.
    double longest_substep() const;
    const StabilityGuard& guard() const { return guard_; }
    const StepCounters& counters() const { return counters_; }

    // Save and restore (base/state_io.h, docs/scoring-and-state.md) of what the next step
    // reads, in the sections of a saved scene: "scene" (the state, the counters, the guard's
    // reference), the frames', the dynamics' (effect counters, each effect's), the
    // integrator's. restore_state reads and checks them all, assigning only when
    // !in.checking(); then restored() bounds the substeps again for the restored effects,
    // the guard keeping the saved reference.
    void save_state(StateWriter& out) const;
    void restore_state(StateReader& in);
    void restored();

private:
    // Stage 1: the substeps of a step of dt, or Error(invalid_argument).
    std::size_t substeps_for(double dt) const;
    // The rollback contract (above).
    void keep_start();
    void back_to_start();
    // Stage 7: one attempt at dt in `substeps` equal substeps; false if the guard rejects it.
    bool attempt_passes(double dt, std::size_t substeps);
    // The message of a step the guard could not save, made before the state goes back
    // (stepper_failure.cpp).
    std::string failure_message(double dt, std::size_t substeps);

    Dynamics& dynamics_;
    RigidFrames& frames_;
    StepperSettings settings_;
    Logger logger_;
    Owned<Integrator> integrator_;
    State state_;
    State start_;  // the state at the step's start, for a rollback
    StabilityGuard guard_;
    double explicit_substep_limit_ = 0.0;  // s
    StepCounters counters_;
    std::string failure_;
};

}  // namespace enteron::mechanics
