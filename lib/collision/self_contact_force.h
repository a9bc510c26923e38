// SPDX-License-Identifier: Apache-2.0
// Contact of the bowel with itself: two collision spheres closer than 2R push apart with
// the penalty law of contact_model.h. Spheres nearer each other along the axis than
// pi R (at rest) are neighbours, not folds, and are skipped: on the tightest bend a tube
// can make (radius R) two points pi R apart along the axis are exactly 2R apart, so the
// window never hides a real contact, and the legs of a U-turn that touch still collide.
// The window is counted in spheres (material, not current, arc length): stretching the
// bowel never turns two neighbours into a contact of a sudden. With several tubes the
// window is each tube's own (its radius, its spacing) and holds within a tube only: the
// spheres of two tubes always may touch.
//
// A pair couples control points far apart along the axis, outside the implicit system's
// band: each sphere's own share of the contact stiffness goes into the system (so the
// implicit step stays stable against the contact), the cross terms stay explicit.
#pragma once

#include <cstdint>
#include <memory_resource>
#include <utility>
#include <vector>

#include "base/geometry.h"
#include "collision/collision_spheres.h"
#include "collision/contact_log.h"
#include "collision/contact_model.h"
#include "collision/spatial_hash.h"
#include "collision/sphere_loads.h"
#include "mechanics/axis_model.h"
#include "mechanics/effect.h"

namespace enteron::collision {

class SelfContactForce final : public mechanics::Effect {
public:
    // `spheres` and `loads` (on the same spheres) are shared with the other contact effects
    // and must outlive this one. evaluate() adds the contact loads to `loads`, which their
    // owner clears before the effects and applies after them (Dynamics: SharedLoads).
    SelfContactForce(CollisionSpheres& spheres, const ContactParameters& contact, const mechanics::State& initial,
                     std::pmr::memory_resource* memory, SphereLoads& loads);

    mechanics::EffectId id() const override { return mechanics::EffectId::self_collision; }
    void evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) override;
    double potential_energy(const mechanics::State& state) const override;
    void add_stiffness_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_damping_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_contacts(mechanics::ContactSummary& summary) const override;
    // Its searches of every sphere so far (the slow path of find_near_pairs).
    void add_work(mechanics::StepWork& work) const override { work.full_contact_searches += searches_; }
    // The near pairs, the grid's filing and the centres they were found at: the
    // continuation of a restored scene finds its pairs in the same order, and so sums the
    // same forces in the same order. Also the contacts of the last evaluation (published).
    void save_state(StateWriter& out) const override;
    void restore_state(StateReader& in) override;

    // The contacts of the last evaluation, one per pair; `other` is the pair's second sphere.
    const ContactLog& contact_log() const { return log_; }

    // How many times the grid was searched: for every sphere (the list of near pairs
    // remade) or for the spheres that moved only (their pairs remade).
    uint64_t grid_searches() const { return searches_ + moved_searches_; }
    uint64_t moved_sphere_searches() const { return moved_searches_; }

private:
    // A pair of spheres in contact: depth (m) and the unit normal from b to a.
    struct Contact {
        uint32_t a, b;
        double depth;
        Vec3 normal;
    };

    // Makes sure the list holds every pair of the placed spheres (outside the neighbour
    // window) closer than 2R. Each sphere keeps the pairs closer than 2.5R found at its
    // last search; only the spheres that moved more than R / 6 since then search again
    // (all at once, from scratch, when many did).
    void find_near_pairs() const;
    // Lists every pair within 2.5R again (after a large motion, or when the list overflowed).
    void search_all_near_pairs() const;
    // Replaces the pairs of the spheres in moved_ by those within 2.5R of them now, after
    // refiling them in the grid (no rebuild: the others stay where they were filed).
    void search_moved_near_pairs() const;
    // Finds the contacts of the spheres placed for `state`, once per placement: the guard's
    // energy after a step and the next step's forces see the same positions.
    void find_contacts(const mechanics::State& state) const;
    // Calls visit(a, b, depth, normal) for every pair of the current spheres in contact,
    // from the listed near pairs or, when the list overflowed, from the grid.
    template <class Visit>
    void search_contacts(Visit&& visit) const;
    // Calls visit(a, b, depth, normal) for every contact found by find_contacts.
    template <class Visit>
    void for_each_contact(Visit&& visit) const;

    CollisionSpheres& spheres_;  // shared with the other contact effects
    mutable std::pmr::vector<double> centers_;  // each sphere's centre at its last search, x y z
    mutable std::pmr::vector<double> positions_;  // the current centres, x y z, packed
    mutable std::pmr::vector<uint32_t> moved_;    // spheres due to search again
    mutable std::pmr::vector<uint8_t> is_moved_;  // 1 for the spheres in moved_
    mutable std::pmr::vector<uint32_t> partners_;  // search_moved_near_pairs: one sphere's new pairs
    mutable uint64_t searches_ = 0;        // of every sphere
    mutable uint64_t moved_searches_ = 0;  // of the moved spheres only
    mutable SpatialHash grid_;  // every sphere filed at centers_
    // Pairs closer than 2.5R at the last search of either sphere, a < b.
    mutable std::pmr::vector<std::pair<uint32_t, uint32_t>> near_pairs_;
    mutable bool near_pairs_complete_ = false;
    mutable std::pmr::vector<uint32_t> touching_;  // search_contacts: the near pairs in contact, by index
    // The contacts of the placement contacts_for_ (0: none yet; placements count from 1);
    // complete unless the list overflowed (then each use searches again).
    mutable std::pmr::vector<Contact> contacts_;
    mutable uint64_t contacts_for_ = 0;
    mutable bool contacts_complete_ = false;
    SphereLoads& loads_;  // shared with the other contact effects
    ContactParameters contact_;
    // Per tube: spheres of that tube fewer apart than this (pi R at rest) are neighbours, never a contact.
    std::pmr::vector<std::size_t> neighbour_spheres_;
    std::pmr::vector<uint32_t> sphere_tube_;  // each sphere's tube: Sphere::tube packed for the pair loop
    bool neighbours(std::size_t i, std::size_t j) const {
        const uint32_t tube = sphere_tube_[i];
        return tube == sphere_tube_[j] && (i > j ? i - j : j - i) < neighbour_spheres_[tube];
    }
    mechanics::ContactSummary last_;
    ContactLog log_;
    std::pmr::memory_resource* memory_;  // restore_state's work space
};

}  // namespace enteron::collision
