// SPDX-License-Identifier: Apache-2.0
#include "collision/self_contact_force.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mechanics/system_matrix.h"

namespace enteron::collision {

namespace {
// A sphere touches at most this many others at once in a dense pile (a bound for the
// explicit integrators' stable substep).
constexpr double kMaxContactsPerSphere = 6.0;
// Pairs are listed up to (2 + this) R apart.
constexpr double kNearMargin = 0.5;
// A sphere searches again once it moved this far (in R) from its last search; see
// find_near_pairs.
constexpr double kMoveLimit = kNearMargin / 3.0;
// The grid files each sphere where it last searched, and a sphere that has not moved
// kMoveLimit since sits that close to its filed place: a pair within (2 + kNearMargin) R
// now is filed within (2 + kNearMargin + kMoveLimit) R, one filed at its current place and
// the other not (search_moved_near_pairs), and a contact within 2 + 2 kMoveLimit
// (search_contacts). The cell covers both.
constexpr double kCellRadii = (2.0 + kNearMargin + kMoveLimit) * 1.001;  // a hair more: rounding in the cell index
}  // namespace

SelfContactForce::SelfContactForce(CollisionSpheres& spheres, const ContactParameters& contact,
                                   const mechanics::State& initial, std::pmr::memory_resource* memory,
                                   SphereLoads& loads)
    : spheres_(spheres),
      centers_(3 * spheres_.size(), 0.0, memory),
      positions_(3 * spheres_.size(), 0.0, memory),
      moved_(memory),
      is_moved_(spheres_.size(), 0, memory),
      partners_(spheres_.size(), 0, memory),
      grid_(spheres_.size(), kCellRadii * spheres_.radius(), memory),
      near_pairs_(memory),
      touching_(memory),
      contacts_(memory),
      loads_(loads),
      contact_(contact),
      neighbour_spheres_(memory),
      sphere_tube_(memory),
      log_(ContactKind::self, kLoggedContactsPerSphere * spheres_.size(), memory),
      memory_(memory) {
    // Room for the densest pile: spheres of radius R whose centres lie within 2.5R of one
    // sphere number at most about 40 (volume ratio), each pair listed once. The contacts
    // are among the listed pairs.
    for (std::size_t tube = 0; tube < spheres_.tube_count(); ++tube)
        neighbour_spheres_.push_back(static_cast<std::size_t>(
            std::ceil(kPi * spheres_.tube_radius(tube) / spheres_.tube_rest_spacing(tube) - 1e-9)));
    for (std::size_t i = 0; i < spheres_.size(); ++i) sphere_tube_.push_back(spheres_[i].tube);
    near_pairs_.reserve(40 * spheres_.size());
    touching_.assign(near_pairs_.capacity(), 0);
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
        const double limit = kMoveLimit * spheres_.radius();
        moved_.clear();
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            const double moved2 = (point_at(positions_.data(), i) - point_at(centers_.data(), i)).squaredNorm();
            // Not within the limit, a non-finite distance included: a sphere filed at a NaN
            // (a blown-up stage, then rolled back) searches again once it is finite.
            if (!(moved2 <= limit * limit)) moved_.push_back(static_cast<uint32_t>(i));
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
        if (!((point_at(positions_.data(), i) - point_at(positions_.data(), j)).squaredNorm() < near * near)) return;
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
    // Refile the moved spheres where they are now, all of them before any searches: a pair
    // of two moved spheres must find the other at its new place.
    for (const uint32_t i : moved_) {
        point_at(centers_.data(), i) = point_at(positions_.data(), i);
        grid_.move(i, point_at(centers_.data(), i));
    }
    moved_searches_ += 1;
    const double near = (2.0 + kNearMargin) * spheres_.radius();
    const double near2 = near * near;
    for (const uint32_t i : moved_) {
        const Vec3 pa = point_at(positions_.data(), i);
        // The partners first, without a branch per candidate (near or not is a coin toss
        // for a branch predictor), then the pairs.
        std::size_t found = 0;
        grid_.for_each_neighbour(i, [&](std::size_t j) {
            const double distance2 = (pa - point_at(positions_.data(), j)).squaredNorm();
            // Near, outside the neighbour window (which holds j == i), and not a pair of two
            // moved spheres, which the first of them lists.
            const bool listed = (distance2 < near2) & !neighbours(i, j) &
                                !((is_moved_[j] != 0) & (j < i));
            partners_[found] = static_cast<uint32_t>(j);
            found += listed ? 1 : 0;
        });
        if (found > near_pairs_.capacity() - near_pairs_.size()) {
            near_pairs_complete_ = false;  // the next placement searches all again
            found = near_pairs_.capacity() - near_pairs_.size();
        }
        for (std::size_t k = 0; k < found; ++k)
            near_pairs_.emplace_back(std::min(i, partners_[k]), std::max(i, partners_[k]));
    }
    for (const uint32_t i : moved_) is_moved_[i] = 0;
}

template <class Visit>
void SelfContactForce::search_contacts(Visit&& visit) const {
    // Two spheres touch closer than the sum of their radii (2R without a radius profile).
    const auto reach_of = [&](std::size_t i, std::size_t j) { return spheres_[i].radius + spheres_[j].radius; };
    const auto contact = [&](std::size_t i, std::size_t j) {
        const double reach = reach_of(i, j);
        const Vec3 d = point_at(positions_.data(), i) - point_at(positions_.data(), j);
        const double distance2 = d.squaredNorm();
        if (!(distance2 < reach * reach)) return;
        const double distance = std::sqrt(distance2);
        // Coincident centres have no direction: any will do, the spring still separates them.
        visit(i, j, reach - distance, distance > 1e-12 ? Vec3(d * (1.0 / distance)) : Vec3::UnitZ());
    };
    if (near_pairs_complete_) {
        // First the listed pairs that touch, without a branch per pair (about one in six
        // touches, 800 of 4800 in the collision bench's pile, in no pattern a branch
        // predictor could learn), then their contacts.
        std::size_t touching = 0;
        for (std::size_t k = 0; k < near_pairs_.size(); ++k) {
            const auto [i, j] = near_pairs_[k];
            const double distance2 = (point_at(positions_.data(), i) - point_at(positions_.data(), j)).squaredNorm();
            const double reach = reach_of(i, j);
            touching_[touching] = static_cast<uint32_t>(k);
            touching += distance2 < reach * reach ? 1 : 0;
        }
        for (std::size_t t = 0; t < touching; ++t) {
            const auto& [i, j] = near_pairs_[touching_[t]];
            contact(i, j);
        }
        return;
    }
    // More near pairs than the list holds (bowel crushed into itself): walk the grid
    // directly rather than drop a contact (see kCellRadii).
    grid_.for_each_candidate_pair([&](std::size_t i, std::size_t j) {
        if (i > j) std::swap(i, j);
        if (neighbours(i, j)) return;
        contact(i, j);
    });
}

void SelfContactForce::find_contacts(const mechanics::State& state) const {
    spheres_.update(state.q.data());
    if (contacts_for_ == spheres_.placement()) return;
    for (std::size_t i = 0; i < spheres_.size(); ++i) point_at(positions_.data(), i) = spheres_[i].center;
    find_near_pairs();
    contacts_.clear();
    contacts_complete_ = true;
    search_contacts([&](std::size_t i, std::size_t j, double depth, const Vec3& n) {
        if (contacts_.size() == contacts_.capacity()) {
            contacts_complete_ = false;  // never grow during a step (see for_each_contact)
            return;
        }
        contacts_.push_back(Contact{static_cast<uint32_t>(i), static_cast<uint32_t>(j), depth, n});
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

// The forces reach `force` when the owner of loads_ applies them, after every contact effect.
void SelfContactForce::evaluate(const mechanics::State& state, double* /*force*/, const mechanics::Linearization* lin) {
    last_ = {};
    log_.clear();
    find_contacts(state);
    const double* velocities = contacts_.empty() && contacts_complete_ ? nullptr : spheres_.velocities(state.v.data());
    for_each_contact([&](std::size_t i, std::size_t j, double depth, const Vec3& n) {
        const Eigen::Map<const Vec3> va = point_at(velocities, i), vb = point_at(velocities, j);
        const ContactForce f = contact_force(contact_, depth, n, va - vb);
        const Vec3 opposite = -f.force;
        last_.count += 1;
        last_.max_penetration = std::max(last_.max_penetration, depth);
        log_.add(static_cast<uint32_t>(i), static_cast<uint32_t>(j), depth,
                 0.5 * (point_at(positions_.data(), i) + point_at(positions_.data(), j)), n, f.force);
        if (lin == nullptr) {
            loads_.add_force(i, f.force);
            loads_.add_force(j, opposite);
            return;
        }
        // Each sphere's own share of the linearisation; the cross terms stay explicit.
        const SphereLoads::LowerTriangle block = SphereLoads::contact_block(n, contact_linearization(f, lin->h));
        loads_.add(i, f.force, n, block, f.stiffness, va);
        loads_.add(j, opposite, n, block, f.stiffness, vb);
    });
}

double SelfContactForce::potential_energy(const mechanics::State& state) const {
    find_contacts(state);
    double energy = 0.0;
    for_each_contact([&](std::size_t, std::size_t, double depth, const Vec3&) {
        energy += 0.5 * contact_.stiffness * depth * depth;
    });
    return energy;
}

void SelfContactForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    // A pair's stiffness k (w_a - w_b)(w_a - w_b)^T is at most 2k (w_a w_a^T + w_b w_b^T).
    spheres_.add_weight_products(2.0 * contact_.stiffness * kMaxContactsPerSphere, bound);
}

void SelfContactForce::add_damping_bound(numerics::ScalarBandMatrix& bound) const {
    const double friction = friction_damping_bound(contact_, spheres_.radius());
    spheres_.add_weight_products(2.0 * (contact_.damping + friction) * kMaxContactsPerSphere, bound);
}

void SelfContactForce::add_contacts(mechanics::ContactSummary& summary) const {
    summary.count += last_.count;
    summary.max_penetration = std::max(summary.max_penetration, last_.max_penetration);
}

void SelfContactForce::save_state(StateWriter& out) const {
    out.begin_section("self_contact", 1);
    out.u32(static_cast<uint32_t>(spheres_.size()));
    out.u64(searches_);
    out.u64(moved_searches_);
    out.u8(near_pairs_complete_ ? 1 : 0);
    out.f64s(centers_.data(), centers_.size());
    out.u32(static_cast<uint32_t>(near_pairs_.size()));
    for (const auto& [a, b] : near_pairs_) {
        out.u32(a);
        out.u32(b);
    }
    grid_.save_filing(out);
    out.u32(last_.count);
    out.f64(last_.max_penetration);
    log_.save_state(out);
    out.end_section();
}

void SelfContactForce::restore_state(StateReader& in) {
    in.begin_section("self_contact", 1);
    const std::size_t count = spheres_.size();
    if (in.u32("collision spheres") != count) in.fail("saved with another number of collision spheres");
    const uint64_t searches = in.u64("searches");
    const uint64_t moved_searches = in.u64("moved-sphere searches");
    const bool complete = in.flag("near pairs complete");
    // A centre may be NaN: a sphere filed where a rejected attempt blew up searches again.
    in.any_f64s("sphere centres at their last search", centers_.size(), in.checking() ? nullptr : centers_.data());
    const uint32_t pairs = in.count("near pairs", near_pairs_.capacity());
    if (!in.checking()) near_pairs_.clear();
    for (uint32_t k = 0; k < pairs; ++k) {
        const uint32_t a = in.index("near pair sphere", count), b = in.index("near pair sphere", count);
        if (!(a < b) || neighbours(a, b)) in.fail("a near pair of neighbouring or unordered spheres");
        if (!in.checking()) near_pairs_.emplace_back(a, b);
    }
    grid_.restore_filing(in, centers_.data(), 3, memory_);
    const uint32_t contacts = in.u32("contacts");
    const double max_penetration = in.f64("deepest contact");
    log_.restore_state(in, count, count);
    in.end_section();
    if (in.checking()) return;
    searches_ = searches;
    moved_searches_ = moved_searches;
    near_pairs_complete_ = complete;
    last_ = {contacts, max_penetration};
    contacts_for_ = 0;  // the contacts of the restored placement are found again, from these pairs
}

}  // namespace enteron::collision
