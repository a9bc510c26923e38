#include "collision/sphere_loads.h"

#include <algorithm>

#include "mechanics/system_matrix.h"

namespace enteron::collision {

SphereLoads::SphereLoads(std::size_t spheres, std::pmr::memory_resource* memory)
    : touched_(spheres, 0, memory), loads_(spheres, Load{}, memory) {}

void SphereLoads::clear() { std::fill(touched_.begin(), touched_.end(), uint8_t{0}); }

void SphereLoads::apply(const CollisionSpheres& spheres, double* force, const mechanics::Linearization* lin) const {
    // In sphere order, so that the spheres of one segment (the same four control points)
    // follow each other and share one block.
    mechanics::SegmentBlock block;
    bool open = false;
    for (std::size_t i = 0; i < touched_.size(); ++i) {
        if (touched_[i] == 0) continue;
        const Load& load = loads_[i];
        const spline::SegmentWeights& weights = spheres[i].weights;
        mechanics::add_point_force(weights, load.force, force);
        if (lin == nullptr) continue;
        mechanics::add_point_force(weights, load.stiffness_times_velocity, lin->stiffness_times_velocity);
        if (open && block.first() != weights.first) block.add_to(*lin->system), open = false;
        if (!open) block.reset(weights.first), open = true;
        block.add(weights, load.block);
    }
    if (open) block.add_to(*lin->system);
}

}  // namespace enteron::collision
