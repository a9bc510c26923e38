#include "collision/sphere_loads.h"

#include <algorithm>

#include "mechanics/system_matrix.h"

namespace enteron::collision {

SphereLoads::SphereLoads(std::size_t spheres, std::pmr::memory_resource* memory)
    : slot_(spheres, -1, memory), loads_(memory) {
    loads_.reserve(spheres);  // never grows during a step
}

void SphereLoads::clear() {
    std::fill(slot_.begin(), slot_.end(), -1);
    loads_.clear();
}

SphereLoads::Load& SphereLoads::at(std::size_t i) {
    if (slot_[i] < 0) {
        slot_[i] = static_cast<int32_t>(loads_.size());
        loads_.push_back(Load{});
    }
    return loads_[static_cast<std::size_t>(slot_[i])];
}

void SphereLoads::add_force(std::size_t i, const double f[3]) {
    Load& load = at(i);
    for (int c = 0; c < 3; ++c) load.force[c] += f[c];
}

void SphereLoads::add(std::size_t i, const double f[3], const double n[3], double axial, double transverse,
                      double stiffness, const double v[3]) {
    Load& load = at(i);
    const double hv = stiffness * (n[0] * v[0] + n[1] * v[1] + n[2] * v[2]);
    for (int c = 0; c < 3; ++c) {
        load.force[c] += f[c];
        load.stiffness_times_velocity[c] += hv * n[c];
    }
    double* b = load.block;
    b[0] += axial * n[0] * n[0] + transverse;
    b[1] += axial * n[1] * n[0];
    b[2] += axial * n[1] * n[1] + transverse;
    b[3] += axial * n[2] * n[0];
    b[4] += axial * n[2] * n[1];
    b[5] += axial * n[2] * n[2] + transverse;
}

void SphereLoads::apply(const CollisionSpheres& spheres, double* force, const mechanics::Linearization* lin) const {
    if (loads_.empty()) return;
    // In sphere order, so that the spheres of one segment (the same four control points)
    // follow each other and share one block.
    mechanics::SegmentBlock block;
    bool open = false;
    for (std::size_t i = 0; i < slot_.size(); ++i) {
        if (slot_[i] < 0) continue;
        const Load& load = loads_[static_cast<std::size_t>(slot_[i])];
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
