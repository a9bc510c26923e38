// SPDX-License-Identifier: Apache-2.0
// An effect adds generalised forces F(q, v, t) on the control points. Every effect maps a
// force f acting at spline parameter s to the control points the same way, through the
// basis weights: F_j += w_j(s) f.
//
// For the implicit integrator an effect also gives its linearisation, the stiffness
// H = -dF/dq and the damping C = -dF/dv, both symmetric positive semi-definite and within
// the system's band. Couplings outside the band (contacts between distant folds) stay
// explicit.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mechanics/effect_id.h"
#include "mechanics/state.h"
#include "mechanics/system_matrix.h"
#include "spline/gram_matrix.h"

namespace enteron {
class Fingerprint;
class StateWriter;
class StateReader;
}  // namespace enteron

namespace enteron::mechanics {

class AxialBlocks;
class BorderedSystem;

// What the implicit integrator asks of an effect: add h C + h^2 H into `system` and H v
// into `stiffness_times_velocity` (3n values). The axis' axial laws (stretch, axial
// damping) put their blocks into `axial` when it is given, and Dynamics::forces adds those
// to the system once, after every effect and before the pins; without it each law adds its own.
//
// An effect whose forces depend on unknowns of its own (a tool's proxy, a massless body held
// between the bowel and the device) adds them to `border` (bordered_system.h) when it is
// given; the implicit integrator solves them with the bowel and reports their solution.
struct Linearization {
    SystemMatrix* system;
    double h;
    double* stiffness_times_velocity;
    AxialBlocks* axial = nullptr;
    BorderedSystem* border = nullptr;
};

// Loads that several effects gather during one evaluation and that reach the generalised
// forces (and, with a linearisation, the implicit system) once, after every effect has added
// its part: the contact effects' loads per collision sphere. Dynamics clears them before
// the effects run and applies them after.
class SharedLoads {
public:
    virtual ~SharedLoads() = default;
    virtual void clear() = 0;
    virtual void apply(double* force, const Linearization* lin) const = 0;
};

// Contacts an effect made in its last evaluation (for ent_stats).
struct ContactSummary {
    uint32_t count = 0;
    double max_penetration = 0.0;  // m
};

class Effect {
public:
    virtual ~Effect() = default;
    virtual EffectId id() const = 0;

    // Adds F(state) into force (3n values) and, when lin is not null, the state-dependent
    // part of the linearisation.
    virtual void evaluate(const State& state, double* force, const Linearization* lin) = 0;

    // Adds the part of h C + h^2 H that never changes (called once per substep length).
    virtual void add_constant_linearization(double /*h*/, SystemMatrix& /*system*/) const {}

    // Potential energy, J (0 for effects that have none).
    virtual double potential_energy(const State& /*state*/) const { return 0.0; }

    // Upper bounds (per coordinate, n x n) of the stiffness and damping this effect can
    // reach; the explicit integrators' stable substep follows from them.
    virtual void add_stiffness_bound(numerics::ScalarBandMatrix& /*bound*/) const {}
    virtual void add_damping_bound(numerics::ScalarBandMatrix& /*bound*/) const {}

    // Adds the contacts of the last evaluation (effects that make contacts only).
    virtual void add_contacts(ContactSummary& /*summary*/) const {}

    // An upper bound of the work (J) this effect may do on the bowel during the current
    // step from outside the system (a tool driven by the caller); the guard allows that
    // much energy to appear. 0 for effects that only store or dissipate energy.
    virtual double external_work_bound() const { return 0.0; }

    // Step hooks, called by the stepper (stepper.h) in the order the effects were added. A
    // step is begin_step, then begin_attempt before each attempt (the first, and each retry
    // after the guard rolled one back).
    //
    // A step of dt seconds begins (the effects that bound the work of moving frames keep its
    // length for external_work_bound).
    virtual void begin_step(double /*dt*/) {}
    // An attempt begins from the step's start: what the effect changed during a rolled-back
    // attempt goes back (stepper.h's rollback contract), its sums over the attempt start at zero.
    virtual void begin_attempt() {}

    // Save and restore (base/state_io.h, docs/scoring-and-state.md). An effect whose future
    // depends on more than the axis state q, v, t (what it holds between steps, caches whose
    // order the next results depend on, the outputs it publishes) writes that into its own
    // section and reads it back: restore_state reads and validates every value, and assigns
    // them only when !in.checking(). Effects without such state keep these empty defaults.
    virtual void save_state(StateWriter& /*out*/) const {}
    virtual void restore_state(StateReader& /*in*/) {}
};

}  // namespace enteron::mechanics
