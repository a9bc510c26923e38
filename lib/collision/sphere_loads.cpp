// SPDX-License-Identifier: Apache-2.0
#include "collision/sphere_loads.h"

#include <algorithm>

#include "mechanics/system_matrix.h"

namespace enteron::collision {

SphereLoads::SphereLoads(const CollisionSpheres& spheres, std::pmr::memory_resource* memory)
    : spheres_(spheres), touched_(spheres.size(), 0, memory), loads_(spheres.size(), Load{}, memory) {}

void SphereLoads::clear() { std::fill(touched_.begin(), touched_.end(), uint8_t{0}); }

void SphereLoads::apply(double* force, const mechanics::Linearization* lin) const {
    // In sphere order, so that the spheres of one segment (the same four control points)
    // follow each other: their forces, H v products and blocks are summed first, and each
    // segment reaches the generalised forces and the system once.
    mechanics::SegmentBlock block;
    constexpr std::size_t kNone = ~std::size_t{0};
    std::size_t first = kNone;
    // Per control point of the segment (a column each): the force, then H v (zero without a
    // linearisation).
    Eigen::Matrix<double, 6, 4> sums;
    const auto flush = [&] {
        if (first == kNone) return;
        Eigen::Map<Eigen::Matrix<double, 3, 4>>(force + 3 * first) += sums.topRows<3>();
        if (lin == nullptr) return;
        Eigen::Map<Eigen::Matrix<double, 3, 4>>(lin->stiffness_times_velocity + 3 * first) += sums.bottomRows<3>();
        block.add_to(*lin->system);
    };
    for (std::size_t i = 0; i < touched_.size(); ++i) {
        if (touched_[i] == 0) continue;
        const Load& load = loads_[i];
        const spline::SegmentWeights& weights = spheres_[i].weights;
        if (weights.first != first) {
            flush();
            first = weights.first;
            sums.setZero();
            if (lin != nullptr) block.reset(first);
        }
        const Eigen::Map<const Vec6> force_and_hv(load.force_and_hv);
        for (int k = 0; k < 4; ++k) sums.col(k) += weights.w[k] * force_and_hv;
        if (lin != nullptr) block.add(weights, load.block);
    }
    flush();
}

}  // namespace enteron::collision
