// The contact loads of one evaluation gathered per collision sphere. A sphere in a pile
// touches several others and the walls at once: its forces, H v products and linearised
// blocks are summed first, and each sphere (each segment, for the blocks) then reaches the
// control points once, instead of one pass over the implicit system's band per contact.
// The scene gives one set to all its contact effects (self-contact and environment), which
// Dynamics applies once after they have all added theirs (SharedLoads); an effect made on
// its own keeps its own set and applies it itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "mechanics/effect.h"

namespace enteron::collision {

class SphereLoads final : public mechanics::SharedLoads {
public:
    // `spheres` must outlive the loads.
    SphereLoads(const CollisionSpheres& spheres, std::pmr::memory_resource* memory);

    // Forgets the loads of the last evaluation.
    void clear() override;

    // A force f (N) on sphere i, without linearisation (the explicit integrators).
    void add_force(std::size_t i, const double f[3]) {
        Load& load = at(i);
        for (int c = 0; c < 3; ++c) load.force_and_hv[c] += f[c];
    }

    // The system block of a contact along the unit normal n, axial n n^T + transverse I
    // (contact_linearization), as a lower triangle: xx, yx, yy, zx, zy, zz. A pair's two
    // spheres share it.
    static void contact_block(const double n[3], const ContactLinearization& l, double block[6]) {
        const double axial = l.axial, transverse = l.transverse;
        block[0] = axial * n[0] * n[0] + transverse;
        block[1] = axial * n[1] * n[0];
        block[2] = axial * n[1] * n[1] + transverse;
        block[3] = axial * n[2] * n[0];
        block[4] = axial * n[2] * n[1];
        block[5] = axial * n[2] * n[2] + transverse;
    }

    // A force f on sphere i with its linearisation along the unit normal n: the system
    // block (contact_block) and the product H v = stiffness (n . v) n for the sphere's
    // velocity v.
    void add(std::size_t i, const double f[3], const double n[3], const double block[6], double stiffness,
             const double v[3]) {
        Load& load = at(i);
        const double hv = stiffness * (n[0] * v[0] + n[1] * v[1] + n[2] * v[2]);
        for (int c = 0; c < 3; ++c) {
            load.force_and_hv[c] += f[c];
            load.force_and_hv[3 + c] += hv * n[c];
        }
        for (int e = 0; e < 6; ++e) load.block[e] += block[e];
    }

    // Adds the gathered loads to the generalised forces (3n values) and, when lin is not
    // null, to the implicit system and H v.
    void apply(double* force, const mechanics::Linearization* lin) const override;

private:
    struct Load {
        double force_and_hv[6];  // the force (N), then H v, x y z each: one run of six for apply
        double block[6];         // lower triangle: xx, yx, yy, zx, zy, zz
    };
    // Sphere i's load, zeroed when first touched since clear().
    Load& at(std::size_t i) {
        if (touched_[i] == 0) {
            touched_[i] = 1;
            loads_[i] = Load{};
        }
        return loads_[i];
    }

    const CollisionSpheres& spheres_;
    std::pmr::vector<uint8_t> touched_;  // per sphere: 1 once it has a load
    std::pmr::vector<Load> loads_;       // per sphere, meaningful where touched
};

}  // namespace enteron::collision
