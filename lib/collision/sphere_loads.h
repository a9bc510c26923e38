// The contact loads of one evaluation gathered per collision sphere. A sphere in a pile
// touches several others and the walls at once: its forces, H v products and linearised
// blocks are summed first, and each sphere (each segment, for the blocks) then reaches the
// control points once, instead of one pass over the implicit system's band per contact.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "collision/collision_spheres.h"
#include "mechanics/effect.h"

namespace enteron::collision {

class SphereLoads {
public:
    SphereLoads(std::size_t spheres, std::pmr::memory_resource* memory);

    // Forgets the loads of the last evaluation.
    void clear();

    // A force f (N) on sphere i, without linearisation (the explicit integrators).
    void add_force(std::size_t i, const double f[3]);

    // A force f on sphere i with its linearisation along the unit normal n: the system
    // block axial n n^T + transverse I (h^2 H + h C of the contact) and the product
    // H v = stiffness (n . v) n for the sphere's velocity v.
    void add(std::size_t i, const double f[3], const double n[3], double axial, double transverse,
             double stiffness, const double v[3]);

    // Adds the gathered loads to the generalised forces (3n values) and, when lin is not
    // null, to the implicit system and H v.
    void apply(const CollisionSpheres& spheres, double* force, const mechanics::Linearization* lin) const;

private:
    struct Load {
        double force[3];
        double stiffness_times_velocity[3];
        double block[6];  // lower triangle: xx, yx, yy, zx, zy, zz
    };
    Load& at(std::size_t i);

    std::pmr::vector<int32_t> slot_;  // per sphere: its entry in loads_, or -1
    std::pmr::vector<Load> loads_;    // the touched spheres, in the order first touched
};

}  // namespace enteron::collision
