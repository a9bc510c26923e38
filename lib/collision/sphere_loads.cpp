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
    // Per control point of the segment: the force, then H v (zero without a linearisation).
    double sums[4][6] = {};
    const auto flush = [&] {
        if (first == kNone) return;
        double* f = force + 3 * first;
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c) f[3 * k + c] += sums[k][c];
        if (lin == nullptr) return;
        double* hv = lin->stiffness_times_velocity + 3 * first;
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c) hv[3 * k + c] += sums[k][3 + c];
        block.add_to(*lin->system);
    };
    for (std::size_t i = 0; i < touched_.size(); ++i) {
        if (touched_[i] == 0) continue;
        const Load& load = loads_[i];
        const spline::SegmentWeights& weights = spheres_[i].weights;
        if (weights.first != first) {
            flush();
            first = weights.first;
            for (auto& sum : sums)
                for (double& v : sum) v = 0.0;
            if (lin != nullptr) block.reset(first);
        }
        const double w[4] = {weights.w[0], weights.w[1], weights.w[2], weights.w[3]};
        for (int k = 0; k < 4; ++k)
            for (int e = 0; e < 6; ++e) sums[k][e] += w[k] * load.force_and_hv[e];
        if (lin != nullptr) block.add(weights, load.block);
    }
    flush();
}

}  // namespace enteron::collision
