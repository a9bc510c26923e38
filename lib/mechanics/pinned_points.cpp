#include "mechanics/pinned_points.h"

#include "mechanics/bordered_system.h"

namespace enteron::mechanics {

PinnedPoints::PinnedPoints(const std::vector<uint32_t>& points, std::pmr::memory_resource* memory)
    : points_(points.begin(), points.end(), memory) {}

void PinnedPoints::evaluate(const State& /*state*/, double* force, const Linearization* lin) {
    zero_rows(force);
    if (lin != nullptr) {
        constrain(*lin->system);
        zero_rows(lin->stiffness_times_velocity);
        if (lin->border != nullptr)
            for (uint32_t p : points_)
                for (std::size_t c = 0; c < 3; ++c) lin->border->zero_row(3 * std::size_t{p} + c);
    }
}

void PinnedPoints::constrain(numerics::ScalarBandMatrix& per_point) const {
    for (uint32_t p : points_) per_point.make_identity_row(p);
}

void PinnedPoints::constrain(SystemMatrix& system) const {
    for (uint32_t p : points_)
        for (std::size_t c = 0; c < 3; ++c) system.make_identity_row(3 * std::size_t{p} + c);
}

void PinnedPoints::zero_rows(double* values) const {
    for (uint32_t p : points_)
        for (std::size_t c = 0; c < 3; ++c) values[3 * std::size_t{p} + c] = 0.0;
}

}  // namespace enteron::mechanics
