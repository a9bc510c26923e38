// Contact of the bowel with its rigid surroundings (the abdominal cavity and other organs):
// every collision sphere against every obstacle, penalty response (contact_model.h) mapped
// to the control points through the sphere's basis weights. A contact touches only four
// consecutive control points, so its linearisation goes into the implicit system.
#pragma once

#include <cstdint>
#include <memory_resource>
#include <vector>

#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/obstacle.h"
#include "collision/sphere_loads.h"
#include "mechanics/axis_model.h"
#include "mechanics/effect.h"

namespace enteron::collision {

class EnvironmentForce final : public mechanics::Effect {
public:
    // `spheres` and `loads` (on the same spheres) are shared with the other contact effects
    // and must outlive this one. evaluate() adds the contact loads to `loads`, which their
    // owner clears before the effects and applies after them (Dynamics: SharedLoads).
    EnvironmentForce(CollisionSpheres& spheres, const ContactParameters& contact,
                     const std::vector<Obstacle>& obstacles, const mechanics::State& initial,
                     std::pmr::memory_resource* memory, SphereLoads& loads);

    mechanics::EffectId id() const override { return mechanics::EffectId::environment; }
    void evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) override;
    double potential_energy(const mechanics::State& state) const override;
    void add_stiffness_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_damping_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_contacts(mechanics::ContactSummary& summary) const override { summary_add(summary); }

    // Adds an obstacle (validated; a plane's normal is normalised here). The caller
    // refinalises the dynamics, since the stability bounds change.
    void add_obstacle(const Obstacle& obstacle);

private:
    struct Contact {
        uint32_t sphere;
        ObstacleContact contact;
    };
    // Finds the contacts of the spheres placed for `state`, once per placement: the guard's
    // energy after a step and the next step's forces see the same positions.
    void find_contacts(const mechanics::State& state) const;
    void summary_add(mechanics::ContactSummary& summary) const;
    // Contact planes one sphere may touch at once, summed over the obstacles.
    double max_contacts_per_sphere() const;

    CollisionSpheres& spheres_;  // shared with the other contact effects
    ContactParameters contact_;
    std::pmr::vector<Obstacle> obstacles_;
    // The contacts of the placement contacts_for_ (0: none yet), in sphere order; room for
    // every sphere touching every obstacle as often as it can, so no step allocates.
    mutable std::pmr::vector<Contact> contacts_;
    mutable uint64_t contacts_for_ = 0;
    SphereLoads& loads_;  // shared with the other contact effects
    mechanics::ContactSummary last_;
};

}  // namespace enteron::collision
