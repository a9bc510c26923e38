// Control points held fixed in space. A pinned point's three coordinates become
// constraints: their rows of the mass matrix and of the implicit system are replaced by
// identity rows and their generalised forces by zero, so their acceleration and velocity
// stay exactly zero and the free points see the pinned ones as fixed walls.
//
// Runs after every other effect (Dynamics puts it last) because it overwrites the rows the
// others have filled.
#pragma once

#include <cstdint>
#include <memory_resource>
#include <vector>

#include "mechanics/effect.h"

namespace enteron::mechanics {

class PinnedPoints final : public Effect {
public:
    // `points` are control point indices (< control point count); duplicates are harmless.
    PinnedPoints(const std::vector<uint32_t>& points, std::pmr::memory_resource* memory);

    EffectId id() const override { return EffectId::pinned; }
    void evaluate(const State& state, double* force, const Linearization* lin) override;

    // Makes the pinned rows of a per-point matrix (the mass matrix) identity rows.
    void constrain(numerics::ScalarBandMatrix& per_point) const;
    // Makes the pinned rows of the coordinate system identity rows.
    void constrain(SystemMatrix& system) const;
    // Zeroes the pinned entries of a 3n vector.
    void zero_rows(double* values) const;

private:
    std::pmr::vector<uint32_t> points_;
};

}  // namespace enteron::mechanics
