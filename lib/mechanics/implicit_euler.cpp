#include "mechanics/implicit_euler.h"

namespace enteron::mechanics {

ImplicitEuler::ImplicitEuler(std::size_t coordinates, std::pmr::memory_resource* memory)
    : system_(memory),
      axial_(coordinates / 3, memory),
      rhs_(coordinates, 0.0, memory),
      stiffness_times_velocity_(coordinates, 0.0, memory) {
    system_.resize(coordinates);
}

bool ImplicitEuler::step(Dynamics& dynamics, State& state, double h) {
    system_.assign(dynamics.constant_system(h));
    BorderedSystem& border = dynamics.border();
    border.clear();
    Linearization lin{&system_, h, stiffness_times_velocity_.data(), &axial_, &border};
    dynamics.forces(state, rhs_.data(), &lin);
    const std::size_t m = rhs_.size();
    for (std::size_t k = 0; k < m; ++k) rhs_[k] = h * (rhs_[k] - h * stiffness_times_velocity_[k]);
    if (!system_.factor()) return false;
    system_.solve(rhs_.data());
    border.solve(system_, rhs_.data());  // the bodies of effects that have them (tools' proxies)
    for (std::size_t k = 0; k < m; ++k) {
        state.v[k] += rhs_[k];
        state.q[k] += h * state.v[k];
    }
    state.time += h;
    dynamics.evaluation_used(h, &state);
    return true;
}

}  // namespace enteron::mechanics
