// SPDX-License-Identifier: Apache-2.0
// The time integrators a scene may pick (integrator.h makes them). The numbers are those of
// ENT_INTEGRATOR_* in enteron.h (checked in lib/capi/abi_constants.cpp).
#pragma once

#include <cstdint>

namespace enteron::mechanics {

enum class IntegratorKind : int32_t { rk4 = 0, symplectic_euler = 1, implicit_euler = 2, bdf2 = 3 };

}  // namespace enteron::mechanics
