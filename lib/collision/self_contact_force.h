// Contact of the bowel with itself: two collision spheres closer than 2R push apart with
// the penalty law of contact_model.h. Spheres nearer each other along the axis than
// pi R are neighbours, not folds, and are skipped: on the tightest bend a tube can make
// (radius R) two points pi R apart along the axis are exactly 2R apart, so the window
// never hides a real contact, and the legs of a U-turn that touch still collide.
//
// A pair couples control points far apart along the axis, outside the implicit system's
// band: each sphere's own share of the contact stiffness goes into the system (so the
// implicit step stays stable against the contact), the cross terms stay explicit.
#pragma once

#include <cstdint>
#include <memory_resource>
#include <utility>
#include <vector>

#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/spatial_hash.h"
#include "mechanics/axis_model.h"
#include "mechanics/effect.h"

namespace enteron::collision {

class SelfContactForce final : public mechanics::Effect {
public:
    SelfContactForce(const mechanics::AxisModel& model, double rest_length, double radius, double sphere_spacing,
                     const ContactParameters& contact, const mechanics::State& initial,
                     std::pmr::memory_resource* memory);

    EffectId id() const override { return EffectId::self_collision; }
    void evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) override;
    double potential_energy(const mechanics::State& state) const override;
    void add_stiffness_bound(spline::ScalarBandMatrix& bound) const override;
    void add_damping_bound(spline::ScalarBandMatrix& bound) const override;
    void add_contacts(mechanics::ContactSummary& summary) const override;

    // The arc-length window within which spheres never collide, m.
    double neighbour_window() const { return window_; }
    // How many times the grid was searched (the list of near pairs remade).
    uint64_t grid_searches() const { return searches_; }

private:
    // Places the spheres for `state` and makes sure the list holds every pair (outside the
    // neighbour window) closer than 2R: it searches the grid for the pairs closer than 3R
    // again only when a sphere has moved more than R / 2 since the last search.
    void find_near_pairs(const mechanics::State& state) const;
    // Calls visit(a, b, depth, normal) for every listed pair in contact (normal b to a).
    template <class Visit>
    void for_each_contact(Visit&& visit) const;

    mutable CollisionSpheres spheres_;
    mutable std::pmr::vector<double> centers_;  // the spheres' centres at the last search, x y z each
    mutable uint64_t searches_ = 0;
    mutable SpatialHash grid_;
    // Pairs closer than 3R at the last search (centers_).
    mutable std::pmr::vector<std::pair<uint32_t, uint32_t>> near_pairs_;
    mutable bool near_pairs_complete_ = false;
    ContactParameters contact_;
    double window_;
    mechanics::ContactSummary last_;
};

}  // namespace enteron::collision
