// SPDX-License-Identifier: Apache-2.0
// Symplectic (semi-implicit) Euler: v += h M^-1 F(q, v); q += h v. First order, explicit,
// one force evaluation per substep; without damping it keeps the energy bounded (it
// exactly conserves a nearby "shadow" energy), for h omega < 2.
#pragma once

#include "mechanics/integrator.h"

namespace enteron::mechanics {

class SymplecticEuler final : public Integrator {
public:
    SymplecticEuler(std::size_t coordinates, std::pmr::memory_resource* memory)
        : acceleration_(coordinates, 0.0, memory) {}
    bool step(Dynamics& dynamics, State& state, double h) override;
    double stability_interval() const override { return 2.0; }

private:
    std::pmr::vector<double> acceleration_;
};

}  // namespace enteron::mechanics
