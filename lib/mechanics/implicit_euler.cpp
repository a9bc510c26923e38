#include "mechanics/implicit_euler.h"

namespace enteron::mechanics {

ImplicitEuler::ImplicitEuler(const AxisModel& model, std::pmr::memory_resource* memory)
    : system_(memory),
      axial_(model, memory),
      rhs_(3 * model.control_points, 0.0, memory),
      stiffness_times_velocity_(3 * model.control_points, 0.0, memory) {
    system_.resize(3 * model.control_points);
}

bool ImplicitEuler::step(Dynamics& dynamics, State& state, double h) {
    system_.assign(dynamics.constant_system(h));
    BorderedSystem* border = dynamics.border();  // null with clamped ends
    if (border != nullptr) border->clear();
    Linearization lin{&system_, h, stiffness_times_velocity_.data(), &axial_, border};
    dynamics.forces(state, rhs_.data(), &lin);
    const std::size_t m = rhs_.size();
    for (std::size_t k = 0; k < m; ++k) rhs_[k] = h * (rhs_[k] - h * stiffness_times_velocity_[k]);
    if (!dynamics.solve_velocity_change(system_, rhs_.data(), state, border)) return false;
    for (std::size_t k = 0; k < m; ++k) {
        state.v[k] += rhs_[k];
        state.q[k] += h * state.v[k];
    }
    state.time += h;
    dynamics.evaluation_used(h, &state);
    return true;
}

}  // namespace enteron::mechanics
