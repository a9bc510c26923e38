// SPDX-License-Identifier: Apache-2.0
// Uniform gravity. Its generalised force is F_j = m_j g with m_j = (M 1)_j the row sums of
// the mass matrix (the basis weights sum to one), so a free axis falls exactly with g.
#pragma once

#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "mechanics/axis_model.h"
#include "mechanics/effect.h"

namespace enteron::mechanics {

class GravityForce final : public Effect {
public:
    GravityForce(const AxisModel& model, const Vec3& gravity,
                 std::pmr::memory_resource* memory);

    EffectId id() const override { return EffectId::gravity; }
    void evaluate(const State& state, double* force, const Linearization* lin) override;
    // -m g . centre of mass: zero when the centre of mass is at the origin.
    double potential_energy(const State& state) const override;
    // Between steps: a new gravity (a tilted table), m/s^2.
    void set_gravity(const Vec3& gravity) { gravity_ = gravity; }
    // The gravity (changed between steps by the caller).
    void save_state(StateWriter& out) const override;
    void restore_state(StateReader& in) override;

private:
    Vec3 gravity_;  // m/s^2
    std::pmr::vector<double> lumped_mass_;  // m_j, kg
};

}  // namespace enteron::mechanics
