// SPDX-License-Identifier: Apache-2.0
// Bending elasticity, soft: energy 1/2 EI integral of |d2P/ds2|^2 ds with s the rest arc
// length (ds = l0 dt). Quadratic in q: 1/2 q^T K_b q per coordinate with the constant band
// matrix K_b = (EI / l0^3) Gram(second derivative), built once. The rest shape is
// straight. |d2P/ds2| is the curvature while the axis keeps its rest length, which the
// stiff stretch term enforces.
#pragma once

#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/effect.h"
#include "mechanics/per_coordinate_matrix.h"

namespace enteron::mechanics {

class BendForce final : public Effect {
public:
    BendForce(const AxisModel& model, double bend_stiffness, std::pmr::memory_resource* memory);

    EffectId id() const override { return EffectId::bend; }
    void evaluate(const State& state, double* force, const Linearization* lin) override;
    void add_constant_linearization(double h, SystemMatrix& system) const override;
    double potential_energy(const State& state) const override;
    void add_stiffness_bound(numerics::ScalarBandMatrix& bound) const override;

private:
    numerics::ScalarBandMatrix stiffness_;  // K_b
    PerCoordinateMatrix stiffness_products_;  // K_b again, for K_b q and K_b v
    mutable std::pmr::vector<double> scratch_;  // K_b q for the energy
};

}  // namespace enteron::mechanics
