// SPDX-License-Identifier: Apache-2.0
// A time integrator advances the state of the axis by one substep h. Each owns its work
// buffers, sized once at creation, so a substep allocates nothing.
#pragma once

#include <cstdint>
#include <limits>
#include <memory_resource>

#include "base/memory.h"
#include "mechanics/dynamics.h"
#include "mechanics/integrator_kind.h"

namespace enteron::mechanics {

class Integrator {
public:
    virtual ~Integrator() = default;

    // Advances state by h seconds. Returns false if the implicit system could not be
    // solved; the state is then unspecified (the caller rolls back).
    virtual bool step(Dynamics& dynamics, State& state, double h) = 0;

    // Stability interval beta of the method on the imaginary axis: an explicit method is
    // stable for h (omega + gamma) <= beta. Infinite for an implicit method.
    virtual double stability_interval() const = 0;

    // A multistep method's history of earlier substeps (bdf2.h) is state: save_history keeps
    // a copy when the stepper keeps the step's start, restore_history brings it back with a
    // rolled-back state (stepper.h), and restart forgets it: the next substep starts the
    // method again, after the state was set from outside (Stepper::state_set_from_outside: a
    // pin stopped a point). One-step methods have none.
    virtual void save_history() {}
    virtual void restore_history() {}
    virtual void restart() {}

    // Save and restore (base/state_io.h), as Effect's: an integrator with a history (a
    // multistep method's previous states) writes it into its own section and reads it back,
    // assigning only when !in.checking(). The one-step integrators have none.
    virtual void save_state(StateWriter& /*out*/) const {}
    virtual void restore_state(StateReader& /*in*/) {}
};

Owned<Integrator> make_integrator(IntegratorKind kind, const AxisModel& model, std::pmr::memory_resource* memory);

}  // namespace enteron::mechanics
