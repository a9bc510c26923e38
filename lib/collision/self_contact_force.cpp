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
constexpr double kNearMargin = 0.5;
}  // namespace

SelfContactForce::SelfContactForce(CollisionSpheres& spheres, const ContactParameters& contact,
                                   const mechanics::State& initial, std::pmr::memory_resource* memory)
    : spheres_(spheres),
      centers_(3 * spheres_.size(), 0.0, memory),
      positions_(3 * spheres_.size(), 0.0, memory),
      moved_(memory),
      is_moved_(spheres_.size(), 0, memory),
      grid_(spheres_.size(), (2.0 + kNearMargin) * spheres_.radius(), memory),
      near_pairs_(memory),
      contacts_(memory),
      loads_(spheres_.size(), memory),
      contact_(contact),
      neighbour_spheres_(static_cast<std::size_t>(std::ceil(kPi * spheres_.radius() / spheres_.rest_spacing() - 1e-9))) {
    // Room for the densest pile: spheres of radius R whose centres lie within 2.5R of one
    // sphere number at most about 40 (volume ratio), each pair listed once. The contacts
    // are among the listed pairs.
    near_pairs_.reserve(40 * spheres_.size());
    contacts_.reserve(near_pairs_.capacity());
    moved_.reserve(spheres_.size());
    spheres_.update(initial.q.data());
}

void SelfContactForce::find_near_pairs() const {
    // Why a sphere may wait until it moved mR / 3 (m the margin, R / 6): take a pair not
    // listed, and the later of the two spheres' last searches; the pair was at least
    // (2 + m) R apart then. Since then that sphere moved at most mR / 3, and the other at
    // most 2mR / 3 (mR / 3 on each side of its own last search, which came before). They
    // closed in by at most mR, so they are still at least 2R apart: not in contact.
    if (near_pairs_complete_) {
        const double limit = kNearMargin * spheres_.radius() / 3.0;
        moved_.clear();
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            const double* p = &positions_[3 * i];
            const double d[3] = {p[0] - centers_[3 * i], p[1] - centers_[3 * i + 1], p[2] - centers_[3 * i + 2]};
            if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > limit * limit) moved_.push_back(static_cast<uint32_t>(i));
        }
        if (moved_.empty()) return;
        // A sphere's own search visits 27 cells, the search of all only the forward half.
        if (4 * moved_.size() < spheres_.size()) {
            search_moved_near_pairs();
            return;
        }
    }
    search_all_near_pairs();
}

void SelfContactForce::search_all_near_pairs() const {
    std::copy(positions_.begin(), positions_.end(), centers_.begin());
    grid_.build(positions_.data(), spheres_.size(), 3);
    searches_ += 1;
    near_pairs_.clear();
    near_pairs_complete_ = true;
    const double near = (2.0 + kNearMargin) * spheres_.radius();
    grid_.for_each_candidate_pair([&](std::size_t i, std::size_t j) {
        if (i > j) std::swap(i, j);  // the same orientation of every pair, run to run
        if (neighbours(i, j)) return;
        const double* a = &positions_[3 * i];
        const double* b = &positions_[3 * j];
        const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
        if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < near * near)) return;
        if (near_pairs_.size() == near_pairs_.capacity()) {
            near_pairs_complete_ = false;  // never grow during a step (see search_contacts)
            return;
        }
        near_pairs_.emplace_back(static_cast<uint32_t>(i), static_cast<uint32_t>(j));
    });
}

void SelfContactForce::search_moved_near_pairs() const {
    for (const uint32_t i : moved_) is_moved_[i] = 1;
    // Drop the moved spheres' pairs, keeping the order of the others (run-to-run identity).
    near_pairs_.erase(std::remove_if(near_pairs_.begin(), near_pairs_.end(),
                                     [&](const std::pair<uint32_t, uint32_t>& p) {
                                         return is_moved_[p.first] != 0 || is_moved_[p.second] != 0;
                                     }),
                      near_pairs_.end());
    grid_.build(positions_.data(), spheres_.size(), 3);
    moved_searches_ += 1;
    const double near = (2.0 + kNearMargin) * spheres_.radius();
    for (const uint32_t i : moved_) {
        for (int c = 0; c < 3; ++c) centers_[3 * i + c] = positions_[3 * i + c];
        const double* pa = &positions_[3 * i];
        grid_.for_each_neighbour(i, [&](std::size_t j) {
            // A pair of two moved spheres is listed by the first of them only.
            if (j == i || (is_moved_[j] != 0 && j < i)) return;
            if (neighbours(i, j)) return;
            const double* pb = &positions_[3 * j];
            const double d[3] = {pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]};
            if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < near * near)) return;
            if (near_pairs_.size() == near_pairs_.capacity()) {
                near_pairs_complete_ = false;  // the next placement searches all again
                return;
            }
            near_pairs_.emplace_back(std::min<uint32_t>(i, static_cast<uint32_t>(j)),
                                     std::max<uint32_t>(i, static_cast<uint32_t>(j)));
        });
    }
    for (const uint32_t i : moved_) is_moved_[i] = 0;
}

template <class Visit>
void SelfContactForce::search_contacts(Visit&& visit) const {
    const double reach = 2.0 * spheres_.radius();
    const auto contact = [&](std::size_t i, std::size_t j) {
        const double* a = &positions_[3 * i];
        const double* b = &positions_[3 * j];
        const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
        const double distance2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (!(distance2 < reach * reach)) return;
        const double distance = std::sqrt(distance2);
        // Coincident centres have no direction: any will do, the spring still separates them.
        const double n[3] = {distance > 1e-12 ? d[0] / distance : 0.0, distance > 1e-12 ? d[1] / distance : 0.0,
                             distance > 1e-12 ? d[2] / distance : 1.0};
        visit(i, j, reach - distance, n);
    };
    if (near_pairs_complete_) {
        for (const auto& [i, j] : near_pairs_) contact(i, j);
        return;
    }
    // More near pairs than the list holds (bowel crushed into itself): walk the grid of
    // the current spheres directly rather than drop a contact.
    grid_.for_each_candidate_pair([&](std::size_t i, std::size_t j) {
        if (i > j) std::swap(i, j);
        if (neighbours(i, j)) return;
        contact(i, j);
    });
}

void SelfContactForce::find_contacts(const mechanics::State& state) const {
    spheres_.update(state.q.data());
    if (contacts_for_ == spheres_.placement()) return;
    for (std::size_t i = 0; i < spheres_.size(); ++i)
        for (int c = 0; c < 3; ++c) positions_[3 * i + c] = spheres_[i].center[c];
    find_near_pairs();
    contacts_.clear();
    contacts_complete_ = true;
    search_contacts([&](std::size_t i, std::size_t j, double depth, const double n[3]) {
        if (contacts_.size() == contacts_.capacity()) {
            contacts_complete_ = false;  // never grow during a step (see for_each_contact)
            return;
        }
        contacts_.push_back(Contact{static_cast<uint32_t>(i), static_cast<uint32_t>(j), depth, {n[0], n[1], n[2]}});
    });
    contacts_for_ = spheres_.placement();
}

template <class Visit>
void SelfContactForce::for_each_contact(Visit&& visit) const {
    if (!contacts_complete_) {
        search_contacts(visit);
        return;
    }
    for (const Contact& c : contacts_) visit(c.a, c.b, c.depth, c.normal);
}

void SelfContactForce::evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) {
    last_ = {};
    find_contacts(state);
    loads_.clear();
    for_each_contact([&](std::size_t i, std::size_t j, double depth, const double n[3]) {
        const Sphere& a = spheres_[i];
        const Sphere& b = spheres_[j];
        double va[3], vb[3];
        spline::evaluate(state.v.data(), a.weights, va);
        spline::evaluate(state.v.data(), b.weights, vb);
        const double relative[3] = {va[0] - vb[0], va[1] - vb[1], va[2] - vb[2]};
        const ContactForce f = contact_force(contact_, depth, n, relative);
        const double opposite[3] = {-f.force[0], -f.force[1], -f.force[2]};
        last_.count += 1;
        last_.max_penetration = std::max(last_.max_penetration, depth);
        if (lin == nullptr) {
            loads_.add_force(i, f.force);
            loads_.add_force(j, opposite);
            return;
        }
        // Each sphere's own share of the linearisation; the cross terms stay explicit.
        const double h = lin->h;
        const double axial = h * h * f.stiffness + h * f.damping - h * f.friction_damping;
        const double transverse = h * f.friction_damping;
        loads_.add(i, f.force, n, axial, transverse, f.stiffness, va);
        loads_.add(j, opposite, n, axial, transverse, f.stiffness, vb);
    });
    loads_.apply(spheres_, force, lin);
}

double SelfContactForce::potential_energy(const mechanics::State& state) const {
    find_contacts(state);
    double energy = 0.0;
    for_each_contact([&](std::size_t, std::size_t, double depth, const double*) {
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
