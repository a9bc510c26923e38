// SPDX-License-Identifier: Apache-2.0
#include "mechanics/rk4.h"

namespace enteron::mechanics {

RungeKutta4::RungeKutta4(std::size_t coordinates, std::pmr::memory_resource* memory)
    : stage_(memory),
      acceleration_(coordinates, 0.0, memory),
      sum_q_(coordinates, 0.0, memory),
      sum_v_(coordinates, 0.0, memory) {
    stage_.resize(coordinates / 3);
}

bool RungeKutta4::step(Dynamics& dynamics, State& state, double h) {
    const std::size_t m = acceleration_.size();
    // Slopes k_i = (v_i, a_i); stage i+1 is state + c_i h k_i; result state + h/6 sum b_i k_i.
    static constexpr double kStageOffset[3] = {0.5, 0.5, 1.0};
    static constexpr double kWeight[4] = {1.0, 2.0, 2.0, 1.0};
    stage_.assign(state);
    for (int i = 0; i < 4; ++i) {
        dynamics.acceleration(stage_, acceleration_.data());
        const double w = kWeight[i] * h / 6.0;
        dynamics.evaluation_used(w, nullptr);
        for (std::size_t k = 0; k < m; ++k) {
            const double slope_q = stage_.v[k];
            const double slope_v = acceleration_[k];
            sum_q_[k] = (i == 0 ? 0.0 : sum_q_[k]) + w * slope_q;
            sum_v_[k] = (i == 0 ? 0.0 : sum_v_[k]) + w * slope_v;
            if (i < 3) {
                const double c = kStageOffset[i] * h;
                stage_.q[k] = state.q[k] + c * slope_q;
                stage_.v[k] = state.v[k] + c * slope_v;
            }
        }
        if (i < 3) stage_.time = state.time + kStageOffset[i] * h;
    }
    for (std::size_t k = 0; k < m; ++k) {
        state.q[k] += sum_q_[k];
        state.v[k] += sum_v_[k];
    }
    state.time += h;
    return true;
}

}  // namespace enteron::mechanics
