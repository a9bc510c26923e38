// SPDX-License-Identifier: Apache-2.0
// An effect driven from outside the scene: the tools, whose commands come from the caller's
// threads before a step and whose outputs go back to them after it. Beyond an Effect's
// hooks, the stepper (stepper.h) hands it the commands at the step's start and the verdict
// at its end, and the integrators tell it how they used each of its evaluations, so that
// what it reports is what the bowel received.
#pragma once

#include <cstddef>

#include "mechanics/effect.h"

namespace enteron::mechanics {

class DrivenEffect : public Effect {
public:
    // Before the first attempt of a step of dt seconds from `state`: takes the commands
    // posted since the last step. True if that changed the energy the effect stores (a grasp
    // taken or let go), so that the guard measures it again.
    virtual bool take_commands(const State& state, double dt) = 0;

    // How the integrator used the effect's last evaluation, so that an effect that reports
    // the force it applied (the tools' wrench) reports exactly what the bowel received. The
    // evaluation's forces acted for `duration` seconds of the substep (an explicit method:
    // its weight of that evaluation, h b_i for the stages of RK4, h for symplectic Euler). An
    // implicit method gives `after`, the state at the end of the substep: its linearised
    // forces reached F - H (q_after - q) - C (v_after - v) there, with q, v the evaluation's
    // state, and its border unknowns are solved. Null for explicit methods.
    virtual void evaluation_used(double duration, const State* after) = 0;

    // Unknowns the effect adds to the implicit system's border (bordered_system.h): the
    // bodies it may add in one evaluation (each with three unknowns). Asked by
    // Dynamics::finalize, which sizes the border once.
    virtual std::size_t border_bodies() const = 0;

    // After the last attempt: accepted (the state moved on) or not (the state is back where
    // the step began). The effect writes its outputs for the scene to publish.
    virtual void end_step(bool accepted) = 0;
};

}  // namespace enteron::mechanics
