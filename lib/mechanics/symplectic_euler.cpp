// SPDX-License-Identifier: Apache-2.0
#include "mechanics/symplectic_euler.h"

namespace enteron::mechanics {

bool SymplecticEuler::step(Dynamics& dynamics, State& state, double h) {
    dynamics.acceleration(state, acceleration_.data());
    dynamics.evaluation_used(h, nullptr);
    const std::size_t m = acceleration_.size();
    for (std::size_t k = 0; k < m; ++k) {
        state.v[k] += h * acceleration_[k];
        state.q[k] += h * state.v[k];
    }
    state.time += h;
    return true;
}

}  // namespace enteron::mechanics
