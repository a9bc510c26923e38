// SPDX-License-Identifier: Apache-2.0
// Contact of the bowel with its rigid surroundings (the abdominal cavity and other organs):
// every collision sphere against every obstacle, penalty response (contact_model.h) mapped
// to the control points through the sphere's basis weights. A contact touches only four
// consecutive control points, so its linearisation goes into the implicit system.
//
// Obstacles move: each has a frame (mechanics/rigid_frames.h) that the caller poses between
// steps. The contact law sees the bowel's velocity relative to the obstacle's surface, so
// damping and friction act on a moving organ. Once an obstacle has moved, each of its contacts
// pushes with at most k R (the force of a contact one bowel radius deep): an organ that
// jumps sweeps through the bowel with a bounded force, as a teleported tool does, instead
// of throwing it. The work the moving obstacles do is the guard's to allow: twice the
// largest power of their contacts in any evaluation of the step, times the step.
//
// Obstacles can be removed between steps; their indices stay (a removed one is skipped).
#pragma once

#include <cstdint>
#include <memory>
#include <memory_resource>
#include <vector>

#include "base/logger.h"
#include "collision/collision_spheres.h"
#include "collision/contact_log.h"
#include "collision/contact_model.h"
#include "collision/obstacle.h"
#include "collision/sphere_loads.h"
#include "mechanics/axis_model.h"
#include "mechanics/effect.h"
#include "mechanics/rigid_frames.h"

namespace enteron::collision {

class EnvironmentForce final : public mechanics::Effect {
public:
    // `spheres` and `loads` (on the same spheres) are shared with the other contact effects
    // and `frames` with the attachments; all must outlive this one. evaluate() adds the
    // contact loads to `loads`, which their owner clears before the effects and applies
    // after them (Dynamics: SharedLoads).
    EnvironmentForce(CollisionSpheres& spheres, const ContactParameters& contact, mechanics::RigidFrames& frames,
                     const mechanics::State& initial, std::pmr::memory_resource* memory, SphereLoads& loads);

    mechanics::EffectId id() const override { return mechanics::EffectId::environment; }
    void evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) override;
    double potential_energy(const mechanics::State& state) const override;
    void add_stiffness_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_damping_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_contacts(mechanics::ContactSummary& summary) const override { summary_add(summary); }
    double external_work_bound() const override;
    void begin_step(double dt) override;
    void begin_attempt() override { largest_power_ = 0.0; }
    // Which obstacles were removed, their friction and the contacts of the last evaluation
    // (what it publishes): the contacts are found again from the positions and frames.
    void save_state(StateWriter& out) const override;
    void restore_state(StateReader& in) override;

    // The contacts of the last evaluation; `other` is the obstacle's index.
    const ContactLog& contact_log() const { return log_; }

    // Builds the distance field of a mesh obstacle for a bowel of radius R (allocates from
    // `memory` and takes time: docs/anatomy.md); other kinds are left as they are. With a
    // radius profile R is its largest value and `smallest_radius` its smallest (0: R): the
    // grid stays a quarter of R, and a coarser grid than a quarter of the smallest radius
    // reads exact closest points near the surface (DistanceFieldSettings::refine), so thin
    // spheres meet the mesh as exactly as R's without the (R / r)^3 more voxels.
    static void prepare(Obstacle& obstacle, double radius, std::pmr::memory_resource* memory,
                        double smallest_radius = 0.0);
    // Adds an obstacle (validated, prepared; a plane's normal is normalised here) with a new
    // frame at its pose. Returns its index. The caller refinalizes the dynamics, since the
    // stability bounds change.
    std::size_t add_obstacle(const Obstacle& obstacle);
    // The obstacle as added (a mesh's field prepared), or null if there is none at index.
    const Obstacle* obstacle(std::size_t index) const;
    // The frame of an obstacle (in `frames`).
    std::size_t frame_of(std::size_t index) const { return placed_[index].frame; }
    // Removes an obstacle (its index is not reused; its frame stays where it is).
    void remove_obstacle(std::size_t index);
    // Coulomb coefficient of one obstacle's contacts (>= 0; negative: the scene's).
    void set_friction(std::size_t index, double friction);
    std::size_t size() const { return placed_.size(); }
    std::size_t live_count() const;

private:
    struct Placed {
        Obstacle shape;  // kind and shape in its frame
        std::size_t frame = 0;
        ContactParameters contact;  // the scene's, with this obstacle's friction
        bool removed = false;
    };
    struct Contact {
        uint32_t sphere;
        uint32_t obstacle;        // its index
        ObstacleContact contact;  // normal in the world
    };
    // Finds the contacts of the spheres placed for `state` with the obstacles where they
    // are at time t, once per placement (and time, while obstacles move): the guard's
    // energy after a step and the next step's forces see the same positions.
    void find_contacts(const mechanics::State& state, double t) const;
    void summary_add(mechanics::ContactSummary& summary) const;
    // Contact planes one sphere may touch at once, summed over the obstacles.
    double max_contacts_per_sphere() const;
    double largest_friction() const;

    CollisionSpheres& spheres_;  // shared with the other contact effects
    ContactParameters contact_;
    mechanics::RigidFrames& frames_;
    std::pmr::memory_resource* memory_;
    std::pmr::vector<Placed> placed_;
    // Each obstacle's frame at the time the contacts were found.
    mutable std::pmr::vector<mechanics::FramePlacement> placements_;
    // The contacts of the placement contacts_for_ (0: none yet), in sphere order; room for
    // every sphere touching every obstacle as often as it can, so no step allocates.
    mutable std::pmr::vector<Contact> contacts_;
    mutable uint64_t contacts_for_ = 0;
    mutable double contacts_time_ = 0.0;
    SphereLoads& loads_;  // shared with the other contact effects
    mechanics::ContactSummary last_;
    ContactLog log_;
    double largest_power_ = 0.0;  // W, of the moving obstacles' contacts in this attempt
    double step_dt_ = 0.0;        // s
};

}  // namespace enteron::collision
