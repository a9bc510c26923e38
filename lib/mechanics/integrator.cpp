// SPDX-License-Identifier: Apache-2.0
#include "mechanics/integrator.h"

#include "base/error.h"
#include "mechanics/bdf2.h"
#include "mechanics/implicit_euler.h"
#include "mechanics/rk4.h"
#include "mechanics/symplectic_euler.h"

namespace enteron::mechanics {

Owned<Integrator> make_integrator(IntegratorKind kind, const AxisModel& model, std::pmr::memory_resource* memory) {
    const std::size_t coordinates = 3 * model.control_points;
    switch (kind) {
        case IntegratorKind::rk4: return make_owned<RungeKutta4>(memory, coordinates, memory);
        case IntegratorKind::symplectic_euler: return make_owned<SymplecticEuler>(memory, coordinates, memory);
        case IntegratorKind::implicit_euler: return make_owned<ImplicitEuler>(memory, model, memory);
        case IntegratorKind::bdf2: return make_owned<Bdf2>(memory, model, memory);
    }
    throw Error(ErrorCode::invalid_argument, "unknown integrator");
}

}  // namespace enteron::mechanics
