// SPDX-License-Identifier: Apache-2.0
// The contact loads of one evaluation gathered per collision sphere. A sphere in a pile
// touches several others and the walls at once: its forces, H v products and linearised
// blocks are summed first, and each sphere (each segment, for the blocks) then reaches the
// control points once, instead of one pass over the implicit system's band per contact.
// The scene gives one set to all its contact effects (self-contact and environment), which
// Dynamics applies once after they have all added theirs (SharedLoads).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
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
    void add_force(std::size_t i, const Vec3& f) { at(i).force() += f; }

    // A symmetric 3 x 3 block by its lower triangle: xx, yx, yy, zx, zy, zz.
    using LowerTriangle = std::array<double, 6>;

    // The system block of a contact along the unit normal n, axial n n^T + transverse I
    // (contact_linearization). A pair's two spheres share it.
    static LowerTriangle contact_block(const Vec3& n, const ContactLinearization& l) {
        const Vec3 an = l.axial * n;
        return {an.x() * n.x() + l.transverse, an.y() * n.x(), an.y() * n.y() + l.transverse,
                an.z() * n.x(),                an.z() * n.y(), an.z() * n.z() + l.transverse};
    }

    // A force f on sphere i with its linearisation along the unit normal n: the system
    // block (contact_block) and the product H v = stiffness (n . v) n for the sphere's
    // velocity v.
    void add(std::size_t i, const Vec3& f, const Vec3& n, const LowerTriangle& block, double stiffness,
             const Vec3& v) {
        Load& load = at(i);
        load.force() += f;
        load.stiffness_times_velocity() += (stiffness * n.dot(v)) * n;
        Eigen::Map<Vec6>(load.block) += Eigen::Map<const Vec6>(block.data());
    }

    // Adds the gathered loads to the generalised forces (3n values) and, when lin is not
    // null, to the implicit system and H v.
    void apply(double* force, const mechanics::Linearization* lin) const override;

private:
    using Vec6 = Eigen::Matrix<double, 6, 1>;
    struct Load {
        double force_and_hv[6];  // the force (N), then H v, x y z each: one run of six for apply
        double block[6];         // lower triangle: xx, yx, yy, zx, zy, zz
        Eigen::Map<Vec3> force() { return Eigen::Map<Vec3>(force_and_hv); }
        Eigen::Map<Vec3> stiffness_times_velocity() { return Eigen::Map<Vec3>(force_and_hv + 3); }
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
