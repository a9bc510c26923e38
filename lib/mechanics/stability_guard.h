// SPDX-License-Identifier: Apache-2.0
// The stability guard: judges each attempt of a step, so that the scene can roll a bad one
// back and retry it with halved substeps. An attempt passes when
//   - every position and velocity stays finite (checked after each substep, so that an
//     attempt that blew up stops at once) and the implicit solve succeeded;
//   - no control point is faster than max_speed at the end of the step;
//   - the energy (kinetic + potential) grew by no more than an allowance, plus the work
//     the effects driven from outside (tools) may have done: energy from nothing is the
//     mark of an unstable step long before positions overflow.
// The guard counts the attempts it rejected (the scene's rollbacks) and keeps what it found
// wrong with the last one, for the error message.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mechanics/dynamics.h"
#include "mechanics/state.h"

namespace enteron::mechanics {

// Which check an attempt failed.
enum class GuardCheck {
    passed,
    solver,      // the implicit system could not be solved
    not_finite,  // a position or velocity (or the energy) is NaN or infinite
    speed,       // a control point is faster than max_speed
    energy,      // more energy than the allowance appeared
};

// What the guard found wrong with the last attempt it rejected.
struct GuardFinding {
    GuardCheck check = GuardCheck::passed;
    std::size_t control_point = 0;  // not_finite: the first such point; speed, energy: the fastest
    double value = 0.0;             // speed: that speed, m/s; energy: the energy gained, J
    double limit = 0.0;             // speed: max_speed, m/s; energy: the allowance, J
};

class StabilityGuard {
public:
    // The allowance for energy appearing in one step is a fraction of the kinetic and
    // deformation energy: an explicit method's energy wobbles by much less (stability suite:
    // under 0.4 %), while an implicit step whose contacts appeared within it can gain tens
    // of percent and, step after step, pile up joules from nothing (50 ms steps in a dense
    // pile went from 0.6 J to 12.9 J with an allowance of 100 %; 1 % refuses legitimate
    // steps out of a deep initial overlap). Below a floor (a bowel at rest) the allowance
    // is the kinetic energy of the whole bowel at kEnergyFloorSpeed.
    static constexpr double kEnergyGrowthFactor = 0.1;
    static constexpr double kEnergyFloorSpeed = 0.1;  // m/s

    // max_speed in m/s; total_mass of the bowel in kg (for the allowance's floor).
    StabilityGuard(double max_speed, double total_mass);

    // The energies of the accepted state that the next attempts are measured against.
    void set_reference(const Dynamics::Energies& energies) { reference_ = energies; }
    const Dynamics::Energies& reference() const { return reference_; }

    // After each substep: `solved` is the integrator's answer. False if the solve failed or
    // a position or velocity is not finite (the attempt is then rejected).
    bool substep_passes(bool solved, const State& state);
    // After the last substep: the speed, then the energy (dynamics' energies of `state` and
    // the work its effects may have done from outside). On success the state's energies
    // become the reference.
    bool step_passes(const State& state, const Dynamics& dynamics);

    // The two end-of-step checks on their own.
    bool speed_passes(const State& state);
    bool energy_passes(const Dynamics::Energies& after, double external_work);
    // Energy (J) a step may gain from the reference, besides the external work.
    double energy_allowance() const;

    // Attempts rejected so far (restored with a saved state).
    uint64_t rollbacks() const { return rollbacks_; }
    void set_rollbacks(uint64_t rollbacks) { rollbacks_ = rollbacks; }
    // What was wrong with the last rejected attempt.
    const GuardFinding& last_finding() const { return finding_; }

private:
    bool reject(const GuardFinding& finding);

    double max_speed_;
    double total_mass_;
    Dynamics::Energies reference_;
    uint64_t rollbacks_ = 0;
    GuardFinding finding_;
};

// "non-finite", "speed", ...: the check's name for messages.
const char* guard_check_name(GuardCheck check);

}  // namespace enteron::mechanics
