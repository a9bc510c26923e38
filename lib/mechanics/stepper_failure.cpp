// SPDX-License-Identifier: Apache-2.0
// The message of a step that stayed unstable (stepper.h): the check that failed and by how
// much, the control point, and the effect that most likely drove it: the strongest force on
// that point at the start of the step, or the effect whose energy grew the most. Off the
// stepping path: it evaluates the effects again, one by one.
#include <cmath>
#include <cstdio>

#include "mechanics/stepper.h"

namespace enteron::mechanics {

std::string Stepper::failure_message(double dt, std::size_t substeps) {
    const GuardFinding& finding = guard_.last_finding();
    const std::size_t point = finding.control_point;
    char what[320];
    switch (finding.check) {
        case GuardCheck::solver:
            std::snprintf(what, sizeof what, "the implicit solve failed (its system was not positive definite)");
            break;
        case GuardCheck::not_finite:
            if (std::isfinite(finding.value))
                std::snprintf(what, sizeof what, "non-finite: control point %zu's position or velocity became NaN or "
                              "infinite", point);
            else
                std::snprintf(what, sizeof what, "non-finite: the energy became %.3g J", finding.value);
            break;
        case GuardCheck::speed:
            std::snprintf(what, sizeof what, "speed: control point %zu moved at %.3g m/s, %.3g times max_speed (%g m/s)",
                          point, finding.value, finding.value / finding.limit, finding.limit);
            break;
        case GuardCheck::energy:
            std::snprintf(what, sizeof what,
                          "energy: the bowel gained %.3g J in the step, %.3g J more than the %.3g J allowed (fastest: "
                          "control point %zu)", finding.value, finding.value - finding.limit, finding.limit, point);
            break;
        case GuardCheck::passed: std::snprintf(what, sizeof what, "none"); break;
    }
    char culprit[200] = "";
    const Dynamics::Culprit gain = finding.check == GuardCheck::energy ? dynamics_.largest_energy_gain(start_, state_)
                                                                         : Dynamics::Culprit{};
    if (gain.found) {
        std::snprintf(culprit, sizeof culprit, "; the largest gain was in %s's potential energy (%+.3g J)",
                      effect_name(gain.effect), gain.amount);
    } else if (finding.check != GuardCheck::solver) {
        const Dynamics::Culprit force = dynamics_.strongest_force_at(start_, point);
        if (force.found)
            std::snprintf(culprit, sizeof culprit,
                          "; the largest force on control point %zu at the start of the step was %s's (%.3g N)", point,
                          effect_name(force.effect), force.amount);
    }
    char message[700];
    std::snprintf(message, sizeof message,
                  "the step of %g s at t = %g s stayed unstable after %zu subdivisions (%zu substeps in the last "
                  "attempt); the guard's last check failed: %s%s; the state is unchanged",
                  dt, start_.time, settings_.max_subdivisions, substeps << settings_.max_subdivisions, what, culprit);
    return message;
}

}  // namespace enteron::mechanics
