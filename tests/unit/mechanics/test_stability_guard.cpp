// SPDX-License-Identifier: Apache-2.0
// The stability guard (lib/mechanics/stability_guard.h): each check rejects exactly past its
// bound, says what it found (the check, the control point, by how much), and every rejection
// counts one rollback.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory_resource>

#include "base/memory.h"
#include "mechanics/dynamics.h"
#include "mechanics/gravity_force.h"
#include "mechanics/stability_guard.h"
#include "mechanics/state.h"

namespace enteron::mechanics {
namespace {

constexpr std::size_t kStabilityGuardPoints = 6;
constexpr double kMass = 2.0;  // kg: the floor of the allowance is 0.5 * 2 * 0.1^2 = 0.01 J
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

State at_rest() {
    State state;
    state.resize(kStabilityGuardPoints);
    for (std::size_t i = 0; i < kStabilityGuardPoints; ++i) state.q[3 * i] = 0.1 * double(i);
    return state;
}

Dynamics::Energies energies(double kinetic, double potential, double deformation) {
    Dynamics::Energies e;
    e.kinetic = kinetic;
    e.potential = potential;
    e.deformation = deformation;
    return e;
}

TEST(StabilityGuard, AFiniteSubstepPassesAndANonFiniteOneNamesItsControlPoint) {
    StabilityGuard guard(50.0, kMass);
    State state = at_rest();
    EXPECT_TRUE(guard.substep_passes(true, state));
    EXPECT_EQ(guard.rollbacks(), 0u);

    state.q[3 * 3 + 1] = kNaN;
    EXPECT_FALSE(guard.substep_passes(true, state));
    EXPECT_EQ(guard.last_finding().check, GuardCheck::not_finite);
    EXPECT_EQ(guard.last_finding().control_point, 3u);

    state = at_rest();
    state.v[3 * 5 + 2] = -kInf;
    EXPECT_FALSE(guard.substep_passes(true, state));
    EXPECT_EQ(guard.last_finding().control_point, 5u);
    EXPECT_EQ(guard.rollbacks(), 2u);
}

TEST(StabilityGuard, AFailedSolveIsRejected) {
    StabilityGuard guard(50.0, kMass);
    EXPECT_FALSE(guard.substep_passes(false, at_rest()));
    EXPECT_EQ(guard.last_finding().check, GuardCheck::solver);
    EXPECT_EQ(guard.rollbacks(), 1u);
}

TEST(StabilityGuard, TheSpeedLimitIsInclusiveAndNamesTheFastestPoint) {
    StabilityGuard guard(5.0, kMass);
    State state = at_rest();
    state.v[3 * 2 + 0] = 3.0;
    state.v[3 * 2 + 1] = 4.0;  // 5 m/s: exactly the limit
    state.v[3 * 4 + 2] = -1.0;
    EXPECT_TRUE(guard.speed_passes(state));
    state.v[3 * 2 + 1] = 4.0001;
    EXPECT_FALSE(guard.speed_passes(state));
    const GuardFinding& finding = guard.last_finding();
    EXPECT_EQ(finding.check, GuardCheck::speed);
    EXPECT_EQ(finding.control_point, 2u);
    EXPECT_NEAR(finding.value, std::sqrt(9.0 + 4.0001 * 4.0001), 1e-12);
    EXPECT_EQ(finding.limit, 5.0);
    EXPECT_EQ(guard.rollbacks(), 1u);
}

TEST(StabilityGuard, TheEnergyAllowanceIsATenthOfKineticAndDeformationEnergyAboveAFloor) {
    StabilityGuard guard(50.0, kMass);
    // 0.1 x (1 + 2) = 0.3 J; gravity's part of the potential (3 - 2) earns nothing.
    guard.set_reference(energies(1.0, 3.0, 2.0));
    EXPECT_DOUBLE_EQ(guard.energy_allowance(), 0.3);
    EXPECT_TRUE(guard.energy_passes(energies(1.3, 3.0, 2.0), 0.0));  // exactly the allowance
    EXPECT_FALSE(guard.energy_passes(energies(1.31, 3.0, 2.0), 0.0));
    const GuardFinding& finding = guard.last_finding();
    EXPECT_EQ(finding.check, GuardCheck::energy);
    EXPECT_NEAR(finding.value, 0.31, 1e-12);  // gained
    EXPECT_NEAR(finding.limit, 0.3, 1e-12);   // allowed
    // Work done from outside (a tool) is allowed on top.
    EXPECT_TRUE(guard.energy_passes(energies(1.5, 3.0, 2.0), 0.2));
    EXPECT_FALSE(guard.energy_passes(energies(1.5, 3.0, 2.0), 0.19));

    // A bowel at rest: the floor, the whole mass at 0.1 m/s.
    guard.set_reference(energies(0.0, 0.0, 0.0));
    EXPECT_DOUBLE_EQ(guard.energy_allowance(), 0.5 * kMass * 0.1 * 0.1);
    EXPECT_TRUE(guard.energy_passes(energies(0.01, 0.0, 0.0), 0.0));
    EXPECT_FALSE(guard.energy_passes(energies(0.0101, 0.0, 0.0), 0.0));
}

TEST(StabilityGuard, ANonFiniteEnergyIsRejectedWhateverTheAllowance) {
    StabilityGuard guard(50.0, kMass);
    guard.set_reference(energies(1.0, 1.0, 1.0));
    EXPECT_FALSE(guard.energy_passes(energies(kInf, 0.0, 0.0), 1e300));
    EXPECT_EQ(guard.last_finding().check, GuardCheck::not_finite);
    EXPECT_FALSE(guard.energy_passes(energies(1.0, kNaN, 0.0), 1e300));
    EXPECT_EQ(guard.rollbacks(), 2u);
}

TEST(StabilityGuard, EveryRejectionCountsOneRollbackAndPassesCountNone) {
    StabilityGuard guard(1.0, kMass);
    State fast = at_rest();
    fast.v[0] = 2.0;
    guard.set_reference(energies(0.0, 0.0, 0.0));
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(guard.substep_passes(true, at_rest()));
        EXPECT_TRUE(guard.speed_passes(at_rest()));
        EXPECT_TRUE(guard.energy_passes(energies(0.0, 0.0, 0.0), 0.0));
    }
    EXPECT_EQ(guard.rollbacks(), 0u);
    EXPECT_FALSE(guard.speed_passes(fast));
    EXPECT_FALSE(guard.substep_passes(false, at_rest()));
    EXPECT_FALSE(guard.energy_passes(energies(1.0, 0.0, 0.0), 0.0));
    EXPECT_EQ(guard.rollbacks(), 3u);
}

TEST(StabilityGuard, AnAcceptedStepBecomesTheReference) {
    // A falling bowel: gravity only. The step passes; the reference is then its energies.
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    AxisModel model;
    model.control_points = kStabilityGuardPoints;
    model.rest_segment_length = 0.1;
    model.linear_density = kMass / (0.1 * double(kStabilityGuardPoints - 1));
    Dynamics dynamics(model, memory);
    dynamics.add_effect(make_owned<GravityForce>(memory, model, enteron::Vec3(0.0, 0.0, -9.81), memory));
    dynamics.finalize();

    State state = at_rest();
    StabilityGuard guard(50.0, kMass);
    guard.set_reference(dynamics.energies(state));
    for (double& v : state.v) v = 0.0;
    for (std::size_t i = 0; i < kStabilityGuardPoints; ++i) {
        state.v[3 * i + 2] = -0.1;   // after a fall of 0.5 mm from rest: energy is conserved
        state.q[3 * i + 2] = -0.1 * 0.1 / (2 * 9.81);
    }
    ASSERT_TRUE(guard.step_passes(state, dynamics));
    const Dynamics::Energies expected = dynamics.energies(state);
    EXPECT_EQ(guard.reference().kinetic, expected.kinetic);
    EXPECT_EQ(guard.reference().potential, expected.potential);

    // Twice as fast from the same height: energy from nothing, rejected; the fastest point named.
    State faster = state;
    for (std::size_t i = 0; i < kStabilityGuardPoints; ++i) faster.v[3 * i + 2] = -0.5;
    faster.v[3 * 4 + 2] = -0.6;
    EXPECT_FALSE(guard.step_passes(faster, dynamics));
    EXPECT_EQ(guard.last_finding().check, GuardCheck::energy);
    EXPECT_EQ(guard.last_finding().control_point, 4u);
    EXPECT_EQ(guard.reference().kinetic, expected.kinetic) << "a rejected attempt leaves the reference";
}

}  // namespace
}  // namespace enteron::mechanics
