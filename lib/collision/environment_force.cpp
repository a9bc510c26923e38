#include "collision/environment_force.h"

#include <cmath>

#include "mechanics/system_matrix.h"

namespace enteron::collision {

EnvironmentForce::EnvironmentForce(CollisionSpheres& spheres, const ContactParameters& contact,
                                   const std::vector<Obstacle>& obstacles, const mechanics::State& initial,
                                   std::pmr::memory_resource* memory, SphereLoads& loads)
    : spheres_(spheres),
      contact_(contact),
      obstacles_(memory),
      contacts_(memory),
      loads_(loads) {
    obstacles_.reserve(obstacles.size());
    for (const Obstacle& obstacle : obstacles) add_obstacle(obstacle);
    spheres_.update(initial.q.data());  // the stability bounds use the spheres' weights
}

void EnvironmentForce::add_obstacle(const Obstacle& obstacle) {
    Obstacle o = obstacle;
    if (o.kind == ObstacleKind::plane) o.extent /= o.extent.norm();
    // Room first (this may throw and must then change nothing): every sphere touching every
    // obstacle as often as it can, six walls for a box narrower than a sphere.
    std::size_t per_sphere = o.kind == ObstacleKind::box_inside ? 6 : 1;
    for (const Obstacle& other : obstacles_) per_sphere += other.kind == ObstacleKind::box_inside ? 6 : 1;
    contacts_.reserve(spheres_.size() * per_sphere);
    obstacles_.reserve(obstacles_.size() + 1);
    obstacles_.push_back(o);
    contacts_for_ = 0;  // the contacts found so far miss this obstacle
}

void EnvironmentForce::find_contacts(const mechanics::State& state) const {
    spheres_.update(state.q.data());
    if (contacts_for_ == spheres_.placement()) return;
    contacts_.clear();
    const double r = spheres_.radius();
    for (std::size_t i = 0; i < spheres_.size(); ++i)
        for (const Obstacle& obstacle : obstacles_)
            for_each_contact(obstacle, spheres_[i].center, r, [&](const ObstacleContact& c) {
                // Field by field: a whole-struct copy read the contact just written with
                // wider loads than its stores, which stalls (store-to-load forwarding fails).
                Contact& contact = contacts_.emplace_back();
                contact.sphere = static_cast<uint32_t>(i);
                contact.contact.depth = c.depth;
                contact.contact.normal = c.normal;
            });
    contacts_for_ = spheres_.placement();
}

// The forces reach `force` when the owner of loads_ applies them, after every contact effect.
void EnvironmentForce::evaluate(const mechanics::State& state, double* /*force*/, const mechanics::Linearization* lin) {
    find_contacts(state);
    last_ = {};
    // The velocity of the spheres in contact only (in sphere order: once per sphere); most
    // spheres touch nothing.
    std::size_t have_velocity = spheres_.size();  // the sphere whose velocity v holds
    Vec3 v = Vec3::Zero();
    for (const Contact& contact : contacts_) {
        const std::size_t i = contact.sphere;
        const ObstacleContact& c = contact.contact;
        if (have_velocity != i) v = spline::evaluate(state.v.data(), spheres_[i].weights), have_velocity = i;
        const ContactForce f = contact_force(contact_, c.depth, c.normal, v);
        last_.count += 1;
        last_.max_penetration = std::max(last_.max_penetration, c.depth);
        if (lin == nullptr) {
            loads_.add_force(i, f.force);
            continue;
        }
        loads_.add(i, f.force, c.normal, SphereLoads::contact_block(c.normal, contact_linearization(f, lin->h)),
                   f.stiffness, v);
    }
}

double EnvironmentForce::potential_energy(const mechanics::State& state) const {
    find_contacts(state);
    double energy = 0.0;
    for (const Contact& contact : contacts_) energy += 0.5 * contact_.stiffness * contact.contact.depth * contact.contact.depth;
    return energy;
}

double EnvironmentForce::max_contacts_per_sphere() const {
    double contacts = 0.0;
    for (const Obstacle& obstacle : obstacles_) contacts += obstacle.kind == ObstacleKind::box_inside ? 3.0 : 1.0;
    return contacts;
}

void EnvironmentForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    spheres_.add_weight_products(contact_.stiffness * max_contacts_per_sphere(), bound);
}

void EnvironmentForce::add_damping_bound(numerics::ScalarBandMatrix& bound) const {
    const double friction = friction_damping_bound(contact_, spheres_.radius());
    spheres_.add_weight_products((contact_.damping + friction) * max_contacts_per_sphere(), bound);
}

void EnvironmentForce::summary_add(mechanics::ContactSummary& summary) const {
    summary.count += last_.count;
    summary.max_penetration = std::max(summary.max_penetration, last_.max_penetration);
}

}  // namespace enteron::collision
