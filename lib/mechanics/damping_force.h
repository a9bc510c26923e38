// SPDX-License-Identifier: Apache-2.0
// Damping, three terms that all remove energy:
//  - drag: a force -c_d v per metre of axis (the surrounding tissue and fluid). Its
//    generalised form is -D v with D = c_d l0 Gram(value) = (c_d / mu) M, constant;
//  - stretch damping: an axial force c_s d(eps)/dt against the strain rate, so rigid
//    motion is not damped (integrated at the stretch nodes; its matrix depends on q);
//  - bend damping: -c_b K v with K = Gram(second) / l0^3, constant.
#pragma once

#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/effect.h"
#include "mechanics/per_coordinate_matrix.h"
#include "mechanics/tube_quadrature.h"

namespace enteron::mechanics {

struct DampingCoefficients {
    double drag = 0.0;     // N s / m^2
    double stretch = 0.0;  // N s
    double bend = 0.0;     // N m^2 s
};

class DampingForce final : public Effect {
public:
    DampingForce(const AxisModel& model, const DampingCoefficients& coefficients,
                 std::pmr::memory_resource* memory);

    EffectId id() const override { return EffectId::damping; }
    void evaluate(const State& state, double* force, const Linearization* lin) override;
    void add_constant_linearization(double h, SystemMatrix& system) const override;
    void add_damping_bound(numerics::ScalarBandMatrix& bound) const override;

private:
    void evaluate_tube(const State& state, const TubeNodeRange& tube, double* force, const Linearization* lin);

    AxisModel model_;
    DampingCoefficients coefficients_;
    numerics::ScalarBandMatrix constant_;  // drag + bend damping, per coordinate
    PerCoordinateMatrix constant_products_;  // the same, for its product with v
    std::pmr::vector<spline::QuadratureNode> nodes_;  // every tube's (tube_quadrature.h)
    std::pmr::vector<TubeNodeRange> tubes_;           // each tube's nodes and l0
};

}  // namespace enteron::mechanics
