// Linearised backward Euler (one Newton step of the implicit Euler method, Baraff and
// Witkin 1998):
//   (M + h C + h^2 H) dv = h (F(q, v) - h H v),   v += dv,   q += h v
// with H = -dF/dq and C = -dF/dv from the effects. The system is banded (half bandwidth
// 11 over the 3n coordinates), so its Cholesky factorisation and solve are O(n).
// Unconditionally stable on linear problems, first order, and it dissipates energy.
#pragma once

#include "mechanics/axial_blocks.h"
#include "mechanics/integrator.h"

namespace enteron::mechanics {

class ImplicitEuler final : public Integrator {
public:
    ImplicitEuler(const AxisModel& model, std::pmr::memory_resource* memory);
    bool step(Dynamics& dynamics, State& state, double h) override;
    double stability_interval() const override { return std::numeric_limits<double>::infinity(); }

private:
    SystemMatrix system_;
    AxialBlocks axial_;  // the stretch and axial damping blocks, added to system_ together
    std::pmr::vector<double> rhs_;                       // F, then h (F - h H v), then dv
    std::pmr::vector<double> stiffness_times_velocity_;  // H v
};

}  // namespace enteron::mechanics
