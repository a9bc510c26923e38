// SPDX-License-Identifier: Apache-2.0
// The classic fourth-order Runge-Kutta method on the first-order system (q, v)' = (v, a).
// Four force evaluations per substep; stable for h omega up to about 2.8 on oscillations.
#pragma once

#include "mechanics/integrator.h"

namespace enteron::mechanics {

class RungeKutta4 final : public Integrator {
public:
    RungeKutta4(std::size_t coordinates, std::pmr::memory_resource* memory);
    bool step(Dynamics& dynamics, State& state, double h) override;
    // The RK4 stability region reaches 2.83 on the imaginary and 2.79 on the real axis.
    double stability_interval() const override { return 2.7; }

private:
    State stage_;                           // the state at which a slope is taken
    std::pmr::vector<double> acceleration_; // of the current stage
    std::pmr::vector<double> sum_q_, sum_v_;  // weighted sums of the slopes
};

}  // namespace enteron::mechanics
