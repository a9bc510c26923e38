// SPDX-License-Identifier: Apache-2.0
#include "mechanics/stability_guard.h"

#include <algorithm>
#include <cmath>

namespace enteron::mechanics {

namespace {

// The first control point whose position or velocity is not finite, or `count` if none.
std::size_t first_not_finite(const State& state) {
    const std::size_t count = state.count();
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t k = 3 * i; k < 3 * i + 3; ++k)
            if (!std::isfinite(state.q[k]) || !std::isfinite(state.v[k])) return i;
    return count;
}

// The fastest control point, and its speed (m/s).
std::pair<std::size_t, double> fastest(const State& state) {
    double fastest_squared = 0.0;
    std::size_t fastest_point = 0;
    for (std::size_t i = 0; i + 2 < state.v.size(); i += 3) {
        const double* v = &state.v[i];
        const double squared = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (squared > fastest_squared) {
            fastest_squared = squared;
            fastest_point = i / 3;
        }
    }
    return {fastest_point, std::sqrt(fastest_squared)};
}

}  // namespace

StabilityGuard::StabilityGuard(double max_speed, double total_mass) : max_speed_(max_speed), total_mass_(total_mass) {}

bool StabilityGuard::reject(const GuardFinding& finding) {
    finding_ = finding;
    rollbacks_ += 1;
    return false;
}

bool StabilityGuard::substep_passes(bool solved, const State& state) {
    if (!solved) return reject({GuardCheck::solver, 0, 0.0, 0.0});
    const std::size_t bad = first_not_finite(state);
    if (bad != state.count()) return reject({GuardCheck::not_finite, bad, 0.0, 0.0});
    return true;
}

bool StabilityGuard::speed_passes(const State& state) {
    const auto [point, speed] = fastest(state);
    if (!(speed <= max_speed_)) return reject({GuardCheck::speed, point, speed, max_speed_});
    return true;
}

double StabilityGuard::energy_allowance() const {
    const double floor = 0.5 * total_mass_ * kEnergyFloorSpeed * kEnergyFloorSpeed;
    return std::max(floor, kEnergyGrowthFactor * (reference_.kinetic + reference_.deformation));
}

bool StabilityGuard::energy_passes(const Dynamics::Energies& after, double external_work) {
    const double total = after.kinetic + after.potential;
    const double gained = total - (reference_.kinetic + reference_.potential);
    const double allowance = energy_allowance() + external_work;
    // A state whose energy is not finite is an explosion, whatever the allowance.
    if (!std::isfinite(total)) return reject({GuardCheck::not_finite, 0, total, allowance});
    if (!(total <= reference_.kinetic + reference_.potential + allowance))
        return reject({GuardCheck::energy, 0, gained, allowance});
    return true;
}

bool StabilityGuard::step_passes(const State& state, const Dynamics& dynamics) {
    if (!speed_passes(state)) return false;
    const Dynamics::Energies after = dynamics.energies(state);
    if (!energy_passes(after, dynamics.external_work_bound())) {
        finding_.control_point = fastest(state).first;
        return false;
    }
    reference_ = after;
    return true;
}

const char* guard_check_name(GuardCheck check) {
    switch (check) {
        case GuardCheck::passed: return "passed";
        case GuardCheck::solver: return "implicit solve";
        case GuardCheck::not_finite: return "non-finite";
        case GuardCheck::speed: return "speed";
        case GuardCheck::energy: return "energy";
    }
    return "?";
}

}  // namespace enteron::mechanics
