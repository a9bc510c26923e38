// SPDX-License-Identifier: Apache-2.0
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

// The work buffers of a linearised implicit substep, sized once (implicit Euler's, and
// bdf2's, which takes its first-order substeps with implicit_euler_step).
struct ImplicitWork {
    ImplicitWork(const AxisModel& model, std::pmr::memory_resource* memory);
    SystemMatrix system;
    AxialBlocks axial;  // the stretch and axial damping blocks, added to system together
    std::pmr::vector<double> rhs;                       // F, then h (F - h H v), then dv
    std::pmr::vector<double> stiffness_times_velocity;  // H v
};

// One implicit Euler substep of h seconds (the formula above). False if the system could
// not be solved (the state is then unspecified).
bool implicit_euler_step(Dynamics& dynamics, State& state, double h, ImplicitWork& work);

class ImplicitEuler final : public Integrator {
public:
    ImplicitEuler(const AxisModel& model, std::pmr::memory_resource* memory) : work_(model, memory) {}
    bool step(Dynamics& dynamics, State& state, double h) override {
        return implicit_euler_step(dynamics, state, h, work_);
    }
    double stability_interval() const override { return std::numeric_limits<double>::infinity(); }

private:
    ImplicitWork work_;
};

}  // namespace enteron::mechanics
