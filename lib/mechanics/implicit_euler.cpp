// SPDX-License-Identifier: Apache-2.0
#include "mechanics/implicit_euler.h"

namespace enteron::mechanics {

ImplicitWork::ImplicitWork(const AxisModel& model, std::pmr::memory_resource* memory)
    : system(memory),
      axial(model, memory),
      rhs(3 * model.control_points, 0.0, memory),
      stiffness_times_velocity(3 * model.control_points, 0.0, memory) {
    system.resize(3 * model.control_points);
}

bool implicit_euler_step(Dynamics& dynamics, State& state, double h, ImplicitWork& work) {
    std::pmr::vector<double>& rhs = work.rhs;
    const std::pmr::vector<double>& hv = work.stiffness_times_velocity;
    work.system.assign(dynamics.constant_system(h));
    BorderedSystem* border = dynamics.border();  // null with clamped ends
    if (border != nullptr) border->clear();
    Linearization lin{&work.system, h, work.stiffness_times_velocity.data(), &work.axial, border};
    dynamics.forces(state, rhs.data(), &lin);
    const std::size_t m = rhs.size();
    for (std::size_t k = 0; k < m; ++k) rhs[k] = h * (rhs[k] - h * hv[k]);
    if (!dynamics.solve_velocity_change(work.system, rhs.data(), state, border)) return false;
    for (std::size_t k = 0; k < m; ++k) {
        state.v[k] += rhs[k];
        state.q[k] += h * state.v[k];
    }
    state.time += h;
    dynamics.evaluation_used(h, &state);
    return true;
}

}  // namespace enteron::mechanics
