// SPDX-License-Identifier: Apache-2.0
#include "collision/environment_force.h"

#include <cmath>
#include <string>

#include "base/hot_kernel.h"
#include "mechanics/system_matrix.h"

namespace enteron::collision {

EnvironmentForce::EnvironmentForce(CollisionSpheres& spheres, const ContactParameters& contact,
                                   mechanics::RigidFrames& frames, const mechanics::State& initial,
                                   std::pmr::memory_resource* memory, SphereLoads& loads)
    : spheres_(spheres),
      contact_(contact),
      frames_(frames),
      memory_(memory),
      placed_(memory),
      placements_(memory),
      contacts_(memory),
      loads_(loads),
      log_(ContactKind::obstacle, kLoggedContactsPerSphere * spheres.size(), memory) {
    spheres_.update(initial.q.data());  // the stability bounds use the spheres' weights
}

namespace {
std::size_t contacts_per_sphere(ObstacleKind kind) { return kind == ObstacleKind::box_inside ? 6 : 1; }
}  // namespace

void EnvironmentForce::prepare(Obstacle& obstacle, double radius, std::pmr::memory_resource* memory,
                               double smallest_radius) {
    if (obstacle.kind != ObstacleKind::mesh || obstacle.field) return;
    DistanceFieldSettings settings;
    settings.voxel_size = obstacle.voxel_size > 0.0 ? obstacle.voxel_size : kDefaultVoxelRadii * radius;
    // Exact where contacts are felt: a sphere touches within R, and interpolation reaches
    // two voxels further.
    settings.band = radius + 2.0 * settings.voxel_size;
    const double finest = smallest_radius > 0.0 ? smallest_radius : radius;
    settings.refine = settings.voxel_size > kDefaultVoxelRadii * finest * (1.0 + 1e-9);
    obstacle.field = std::allocate_shared<MeshDistanceField>(std::pmr::polymorphic_allocator<MeshDistanceField>(memory),
                                                             *obstacle.mesh, settings, memory);
    obstacle.mesh.reset();  // the field keeps its own copy
}

std::size_t EnvironmentForce::add_obstacle(const Obstacle& obstacle) {
    Placed placed;
    placed.shape = obstacle;
    if (obstacle.kind == ObstacleKind::plane) placed.shape.extent /= placed.shape.extent.norm();
    placed.contact = contact_;
    if (obstacle.friction >= 0.0) placed.contact.friction = obstacle.friction;
    // Room first (this may throw and must then change nothing): every sphere touching every
    // obstacle as often as it can, six walls for a box narrower than a sphere.
    std::size_t per_sphere = contacts_per_sphere(obstacle.kind);
    for (const Placed& other : placed_) per_sphere += contacts_per_sphere(other.shape.kind);
    contacts_.reserve(spheres_.size() * per_sphere);
    placed_.reserve(placed_.size() + 1);
    placements_.reserve(placed_.size() + 1);
    placed.frame = frames_.add(obstacle.pose);
    placed_.push_back(std::move(placed));
    placements_.emplace_back();
    contacts_for_ = 0;  // the contacts found so far miss this obstacle
    return placed_.size() - 1;
}

const Obstacle* EnvironmentForce::obstacle(std::size_t index) const {
    if (index >= placed_.size() || placed_[index].removed) return nullptr;
    return &placed_[index].shape;
}

void EnvironmentForce::remove_obstacle(std::size_t index) {
    Placed& placed = placed_[index];
    placed.removed = true;
    placed.shape.field.reset();
    contacts_for_ = 0;
}

void EnvironmentForce::set_friction(std::size_t index, double friction) {
    placed_[index].shape.friction = friction;
    placed_[index].contact.friction = friction >= 0.0 ? friction : contact_.friction;
}

std::size_t EnvironmentForce::live_count() const {
    std::size_t count = 0;
    for (const Placed& placed : placed_) count += placed.removed ? 0 : 1;
    return count;
}

ENTERON_HOT_KERNEL void EnvironmentForce::find_contacts(const mechanics::State& state, double t) const {
    spheres_.update(state.q.data());
    const bool moving = frames_.any_moving();
    if (contacts_for_ == spheres_.placement() && (!moving || contacts_time_ == t)) return;
    contacts_.clear();
    for (std::size_t k = 0; k < placed_.size(); ++k) placements_[k] = frames_.at(placed_[k].frame, t);
    for (std::size_t i = 0; i < spheres_.size(); ++i)
        for (std::size_t k = 0; k < placed_.size(); ++k) {
            const double r = spheres_[i].radius;
            const Placed& placed = placed_[k];
            if (placed.removed) continue;
            const mechanics::FramePlacement& frame = placements_[k];
            for_each_contact(placed.shape, frame.to_local(spheres_[i].center), r, [&](const ObstacleContact& c) {
                // Field by field: a whole-struct copy read the contact just written with
                // wider loads than its stores, which stalls (store-to-load forwarding fails).
                Contact& contact = contacts_.emplace_back();
                contact.sphere = static_cast<uint32_t>(i);
                contact.obstacle = static_cast<uint32_t>(k);
                contact.contact.depth = c.depth;
                contact.contact.normal = frame.direction_to_world(c.normal);
            });
        }
    contacts_for_ = spheres_.placement();
    contacts_time_ = t;
}

// The forces reach `force` when the owner of loads_ applies them, after every contact effect.
void EnvironmentForce::evaluate(const mechanics::State& state, double* /*force*/, const mechanics::Linearization* lin) {
    // The implicit step solves for the end of the substep: meet the obstacles where they are then.
    find_contacts(state, state.time + (lin != nullptr ? lin->h : 0.0));
    last_ = {};
    log_.clear();
    double power = 0.0;  // of the moving obstacles' contacts, W
    // The velocity of the spheres in contact only (in sphere order: once per sphere); most
    // spheres touch nothing.
    std::size_t have_velocity = spheres_.size();  // the sphere whose velocity v holds
    Vec3 v = Vec3::Zero();
    for (const Contact& contact : contacts_) {
        const std::size_t i = contact.sphere;
        const double r = spheres_[i].radius;
        const ObstacleContact& c = contact.contact;
        if (have_velocity != i) v = spline::evaluate(state.v.data(), spheres_[i].weights), have_velocity = i;
        const Placed& placed = placed_[contact.obstacle];
        const mechanics::FramePlacement& frame = placements_[contact.obstacle];
        last_.count += 1;
        last_.max_penetration = std::max(last_.max_penetration, c.depth);
        // The point of the obstacle's surface the sphere reaches into.
        const Vec3 surface_point = spheres_[i].center - (r - c.depth) * c.normal;
        if (!frame.kinematic) {
            const ContactForce f = contact_force(placed.contact, c.depth, c.normal, v);
            log_.add(contact.sphere, contact.obstacle, c.depth, surface_point, c.normal, f.force);
            if (lin == nullptr) {
                loads_.add_force(i, f.force);
                continue;
            }
            loads_.add(i, f.force, c.normal, SphereLoads::contact_block(c.normal, contact_linearization(f, lin->h)),
                       f.stiffness, v);
            continue;
        }
        // An obstacle the caller moves: the law sees the velocity relative to its surface at
        // the contact point, and the force is bounded by k R (also once it rests again: the
        // bowel it jumped onto is let out gently).
        const Vec3 surface_velocity = frame.velocity_at(surface_point);
        ContactForce f = contact_force(placed.contact, c.depth, c.normal, v - surface_velocity);
        const double bound = placed.contact.stiffness * r;
        const double magnitude = f.force.norm();
        const double scale = magnitude > bound ? bound / magnitude : 1.0;
        f.force *= scale;
        power += magnitude * scale * surface_velocity.norm();
        log_.add(contact.sphere, contact.obstacle, c.depth, surface_point, c.normal, f.force);
        if (lin == nullptr) {
            loads_.add_force(i, f.force);
            continue;
        }
        ContactLinearization l = contact_linearization(f, lin->h);
        l.axial *= scale;
        l.transverse *= scale;
        // H v with the bowel's own velocity: the force was taken where the obstacle is at the
        // end of the substep, so only the bowel's motion within it remains to linearise.
        loads_.add(i, f.force, c.normal, SphereLoads::contact_block(c.normal, l), scale * f.stiffness, v);
    }
    largest_power_ = std::max(largest_power_, power);
}

double EnvironmentForce::potential_energy(const mechanics::State& state) const {
    find_contacts(state, state.time);
    double energy = 0.0;
    for (const Contact& contact : contacts_) {
        const double r = spheres_[contact.sphere].radius;
        const double k = placed_[contact.obstacle].contact.stiffness, d = contact.contact.depth;
        // A moved obstacle's spring stops growing at depth R (evaluate's bound).
        if (placements_[contact.obstacle].kinematic && d > r)
            energy += k * r * (d - 0.5 * r);
        else
            energy += 0.5 * k * d * d;
    }
    return energy;
}

void EnvironmentForce::begin_step(double dt) {
    step_dt_ = dt;
    largest_power_ = 0.0;
}

double EnvironmentForce::external_work_bound() const { return 2.0 * largest_power_ * step_dt_; }

double EnvironmentForce::max_contacts_per_sphere() const {
    double contacts = 0.0;
    for (const Placed& placed : placed_)
        if (!placed.removed) contacts += placed.shape.kind == ObstacleKind::box_inside ? 3.0 : 1.0;
    return contacts;
}

double EnvironmentForce::largest_friction() const {
    double friction = contact_.friction;
    for (const Placed& placed : placed_)
        if (!placed.removed) friction = std::max(friction, placed.contact.friction);
    return friction;
}

void EnvironmentForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    spheres_.add_weight_products(contact_.stiffness * max_contacts_per_sphere(), bound);
}

void EnvironmentForce::add_damping_bound(numerics::ScalarBandMatrix& bound) const {
    ContactParameters worst = contact_;
    worst.friction = largest_friction();
    const double friction = friction_damping_bound(worst, spheres_.radius());
    spheres_.add_weight_products((contact_.damping + friction) * max_contacts_per_sphere(), bound);
}

void EnvironmentForce::summary_add(mechanics::ContactSummary& summary) const {
    summary.count += last_.count;
    summary.max_penetration = std::max(summary.max_penetration, last_.max_penetration);
}

// The obstacles' set (which were removed) must match; their friction is restored. Their
// frames are the scene's (RigidFrames' own section); the contacts are found again.
void EnvironmentForce::save_state(StateWriter& out) const {
    out.begin_section("environment", 2);
    out.u32(static_cast<uint32_t>(placed_.size()));
    for (const Placed& placed : placed_) {
        out.u8(placed.removed ? 1 : 0);
        out.f64(placed.shape.friction);
    }
    out.u32(last_.count);
    out.f64(last_.max_penetration);
    log_.save_state(out);
    out.end_section();
}

void EnvironmentForce::restore_state(StateReader& in) {
    if (in.begin_section("environment", 2) < 2) in.fail("saved before obstacles could move (version 1); save it again");
    if (in.u32("obstacles") != placed_.size()) in.fail("saved with another number of obstacles");
    for (std::size_t k = 0; k < placed_.size(); ++k) {
        if (in.flag("obstacle removed") != placed_[k].removed)
            in.fail("obstacle " + std::to_string(k) +
                    (placed_[k].removed ? " was removed from this scene but not from the saved one"
                                        : " was removed from the saved scene but not from this one"));
        const double friction = in.f64("obstacle friction");
        if (!in.checking()) set_friction(k, friction);
    }
    const uint32_t contacts = in.u32("contacts");
    const double max_penetration = in.f64("deepest contact");
    log_.restore_state(in, spheres_.size(), placed_.size());
    in.end_section();
    if (in.checking()) return;
    last_ = {contacts, max_penetration};
    contacts_for_ = 0;
}

}  // namespace enteron::collision
