// SPDX-License-Identifier: Apache-2.0
// Axial elasticity, stiff: energy 1/2 EA eps^2 per unit rest length, with the engineering
// strain eps = |dP/ds| - 1 = |dP/dt| / l0 - 1 (the rest state is the axis at its rest
// length, whatever its initial shape). Integrated with 2-point Gauss per segment: 2 (n-1)
// strain samples for 3n coordinates leave the bending modes free, where 3 points per
// segment (about as many samples as coordinates) would lock them and stiffen the bending.
//
// With a stretch stiffness profile, EA(s) is read at each node's rest arc length. With several
// tubes (axis_model.h) each has its own nodes, l0, and EA or profile.
//
// Linearisation: the Hessian of the energy at a node, H = EA [u u^T / l0 + eps/|P'| (I - u u^T)]
// with u the unit tangent, is indefinite when the axis is compressed (eps < 0); the
// transverse term is clamped to eps >= 0 so the implicit system stays positive definite.
#pragma once

#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/effect.h"
#include "mechanics/tube_quadrature.h"

namespace enteron::mechanics {

class StretchForce final : public Effect {
public:
    StretchForce(const AxisModel& model, double stretch_stiffness, std::pmr::memory_resource* memory);

    EffectId id() const override { return EffectId::stretch; }
    void evaluate(const State& state, double* force, const Linearization* lin) override;
    double potential_energy(const State& state) const override;
    void add_stiffness_bound(numerics::ScalarBandMatrix& bound) const override;

private:
    void evaluate_tube(const State& state, const TubeNodeRange& tube, double* force, const Linearization* lin);

    AxisModel model_;
    double stiffness_;  // EA, N (with a profile: its largest value), of the tubes without their own
    std::pmr::vector<spline::QuadratureNode> nodes_;  // every tube's (tube_quadrature.h)
    std::pmr::vector<TubeNodeRange> tubes_;           // each tube's nodes and l0
    std::pmr::vector<double> node_stiffness_;  // EA at each node, N (the profile's, or stiffness_)
};

}  // namespace enteron::mechanics
