#include "collision/self_contact_force.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mechanics/system_matrix.h"

namespace enteron::collision {

namespace {
constexpr double kPi = 3.14159265358979323846;
// A sphere touches at most this many others at once in a dense pile (a bound for the
// explicit integrators' stable substep).
constexpr double kMaxContactsPerSphere = 6.0;
// Pairs are listed up to (2 + this) R apart, the grid's cell size.
constexpr double kNearMargin = 1.0;
}  // namespace

SelfContactForce::SelfContactForce(const mechanics::AxisModel& model, double rest_length, double radius,
                                   double sphere_spacing, const ContactParameters& contact,
                                   const mechanics::State& initial, std::pmr::memory_resource* memory)
    : spheres_(model.control_points, rest_length, sphere_spacing, radius, memory),
      centers_(3 * spheres_.size(), 0.0, memory),
      grid_(spheres_.size(), (2.0 + kNearMargin) * radius, memory),
      near_pairs_(memory),
      contact_(contact),
      window_(kPi * radius) {
    // Room for the densest pile: spheres of radius R whose centres lie within 3R of one
    // sphere number at most about 40 (volume ratio), each pair listed once.
    near_pairs_.reserve(40 * spheres_.size());
    spheres_.update(initial.q.data());
}

void SelfContactForce::find_near_pairs(const mechanics::State& state) const {
    spheres_.update(state.q.data());
    // The list stays exact while no sphere has moved more than half its margin (R / 2)
    // since it was made: two spheres then closed in by at most R, so every pair now closer
    // than 2R was closer than 3R then and is listed. Only then is the grid searched again.
    if (near_pairs_complete_) {
        const double limit = 0.5 * kNearMargin * spheres_.radius();
        double moved = 0.0;
        for (std::size_t i = 0; i < spheres_.size() && moved <= limit * limit; ++i) {
            const double d[3] = {spheres_[i].center[0] - centers_[3 * i], spheres_[i].center[1] - centers_[3 * i + 1],
                                 spheres_[i].center[2] - centers_[3 * i + 2]};
            moved = std::max(moved, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        }
        if (moved <= limit * limit) return;
    }
    for (std::size_t i = 0; i < spheres_.size(); ++i)
        for (int c = 0; c < 3; ++c) centers_[3 * i + c] = spheres_[i].center[c];
    grid_.build(centers_.data(), spheres_.size(), 3);
    searches_ += 1;
    near_pairs_.clear();
    near_pairs_complete_ = true;
    const double near = (2.0 + kNearMargin) * spheres_.radius();
    grid_.for_each_candidate_pair([&](std::size_t i, std::size_t j) {
        if (i > j) std::swap(i, j);  // the same orientation of every pair, run to run
        const Sphere& a = spheres_[i];
        const Sphere& b = spheres_[j];
        if (std::fabs(a.arc_length - b.arc_length) < window_) return;
        const double d[3] = {a.center[0] - b.center[0], a.center[1] - b.center[1], a.center[2] - b.center[2]};
        if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < near * near)) return;
        if (near_pairs_.size() == near_pairs_.capacity()) {
            near_pairs_complete_ = false;  // never grow during a step (see for_each_contact)
            return;
        }
        near_pairs_.emplace_back(static_cast<uint32_t>(i), static_cast<uint32_t>(j));
    });
}

template <class Visit>
void SelfContactForce::for_each_contact(Visit&& visit) const {
    const double reach = 2.0 * spheres_.radius();
    const auto contact = [&](std::size_t i, std::size_t j) {
        const Sphere& a = spheres_[i];
        const Sphere& b = spheres_[j];
        const double d[3] = {a.center[0] - b.center[0], a.center[1] - b.center[1], a.center[2] - b.center[2]};
        const double distance2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (!(distance2 < reach * reach)) return;
        const double distance = std::sqrt(distance2);
        // Coincident centres have no direction: any will do, the spring still separates them.
        const double n[3] = {distance > 1e-12 ? d[0] / distance : 0.0, distance > 1e-12 ? d[1] / distance : 0.0,
                             distance > 1e-12 ? d[2] / distance : 1.0};
        visit(a, b, reach - distance, n);
    };
    if (near_pairs_complete_) {
        for (const auto& [i, j] : near_pairs_) contact(i, j);
        return;
    }
    // More near pairs than the list holds (bowel crushed into itself): walk the grid of
    // the current spheres directly rather than drop a contact.
    grid_.for_each_candidate_pair([&](std::size_t i, std::size_t j) {
        if (i > j) std::swap(i, j);
        if (std::fabs(spheres_[i].arc_length - spheres_[j].arc_length) < window_) return;
        contact(i, j);
    });
}

void SelfContactForce::evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) {
    last_ = {};
    find_near_pairs(state);
    for_each_contact([&](const Sphere& a, const Sphere& b, double depth, const double n[3]) {
        double va[3], vb[3];
        spline::evaluate(state.v.data(), a.weights, va);
        spline::evaluate(state.v.data(), b.weights, vb);
        const double relative[3] = {va[0] - vb[0], va[1] - vb[1], va[2] - vb[2]};
        const ContactForce f = contact_force(contact_, depth, n, relative);
        const double opposite[3] = {-f.force[0], -f.force[1], -f.force[2]};
        mechanics::add_point_force(a.weights, f.force, force);
        mechanics::add_point_force(b.weights, opposite, force);
        last_.count += 1;
        last_.max_penetration = std::max(last_.max_penetration, depth);
        if (lin == nullptr) return;
        const double h = lin->h;
        const double axial = h * h * f.stiffness + h * f.damping - h * f.friction_damping;
        mechanics::add_axial_block(*lin->system, a.weights, n, axial, h * f.friction_damping, 1.0);
        mechanics::add_axial_block(*lin->system, b.weights, n, axial, h * f.friction_damping, 1.0);
        // H v for the diagonal shares only, consistent with the matrix above.
        const double na = f.stiffness * (va[0] * n[0] + va[1] * n[1] + va[2] * n[2]);
        const double nb = f.stiffness * (vb[0] * n[0] + vb[1] * n[1] + vb[2] * n[2]);
        const double ha[3] = {na * n[0], na * n[1], na * n[2]};
        const double hb[3] = {nb * n[0], nb * n[1], nb * n[2]};
        mechanics::add_point_force(a.weights, ha, lin->stiffness_times_velocity);
        mechanics::add_point_force(b.weights, hb, lin->stiffness_times_velocity);
    });
}

double SelfContactForce::potential_energy(const mechanics::State& state) const {
    find_near_pairs(state);
    double energy = 0.0;
    for_each_contact([&](const Sphere&, const Sphere&, double depth, const double*) {
        energy += 0.5 * contact_.stiffness * depth * depth;
    });
    return energy;
}

void SelfContactForce::add_stiffness_bound(spline::ScalarBandMatrix& bound) const {
    // A pair's stiffness k (w_a - w_b)(w_a - w_b)^T is at most 2k (w_a w_a^T + w_b w_b^T).
    spheres_.add_weight_products(2.0 * contact_.stiffness * kMaxContactsPerSphere, bound);
}

void SelfContactForce::add_damping_bound(spline::ScalarBandMatrix& bound) const {
    const double friction = friction_damping_bound(contact_, spheres_.radius());
    spheres_.add_weight_products(2.0 * (contact_.damping + friction) * kMaxContactsPerSphere, bound);
}

void SelfContactForce::add_contacts(mechanics::ContactSummary& summary) const {
    summary.count += last_.count;
    summary.max_penetration = std::max(summary.max_penetration, last_.max_penetration);
}

}  // namespace enteron::collision
