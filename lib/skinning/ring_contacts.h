// SPDX-License-Identifier: Apache-2.0
// One ring of a skin's rays where other folds touch it: the rays cut back to the contact
// surface, the cross-section's lost area given back as a bulge beside the contact
// (contact_profile.h), and every ray kept short of its neighbouring rings (no fold-over,
// fold_over_limit.h). The ring skins (tube, convolution) deform each of their rings with
// it; the point skeleton asks it, per skeleton point, how far its bulge must reach.
//
// One deform(), in four passes over the ring's rays (d_j = cos_j normal + sin_j binormal,
// tilted towards the tangent on an end cap's rows):
//  1. the other folds near the ring (fold_contacts.h), and on each ray their level at the
//     free radius t0_j: x0_j and its slope G_j along the ray (skipping the rays a fold
//     cannot reach, by the level's Lipschitz bound from the last ray measured);
//  2. the rays inside a contact are cut to its surface (solved on the linear model, then
//     once more from the level measured there);
//  3. volume: the ring's cross-section, each fan triangle (c, v_j, v_j+1) weighted by
//     1 - k . (its centroid - c) for the bend of the axis (Pappus: the volume a ring
//     sweeps per unit of arc length), is compared before and after the cut; the bulge's
//     reach w in (0, kMaxBulgeReach] that gives the lost area back is found as a root (the
//     area grows with w), each trial solving every free ray's bulge on its linear
//     model (regula falsi: a few trials). When even the largest bulge cannot give it all back (a ring pressed from all
//     sides), the rest is lost and reported;
//  4. each bulged ray is checked against every fold at its new point (a bulge must not
//     push into a third fold), and every ray is kept short of the fold-over limits of the
//     neighbouring rings.
// Rings of end caps take passes 1, 2 and 4: cut to the contact, no bulge.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/geometry.h"
#include "skinning/contact_profile.h"
#include "skinning/fold_contacts.h"

namespace enteron::skinning {

class RingContacts {
public:
    static constexpr std::size_t kMaxFolds = 8;  // other folds considered per ring

    struct Ring {
        Vec3 centre = Vec3::Zero();     // the ring's axis point, m
        Vec3 normal = Vec3::Zero();     // its frame: normal, binormal, tangent
        Vec3 binormal = Vec3::Zero();
        Vec3 tangent = Vec3::Zero();
        Vec3 curvature = Vec3::Zero();  // dt/ds of the axis there, 1/m
        double arc_length = 0.0;        // of the centre along its tube, m
        uint32_t tube = 0;
        double radius = 0.0;            // R of the tube, m
        const double* cosine = nullptr;  // per ray: cos and sin of its angle around the ring
        const double* sine = nullptr;
        std::size_t rays = 0;
        double tilt = 0.0;               // end caps: the rays' angle towards the tangent, rad
        bool keep_area = true;           // bulge to keep the cross-section (body rings)
        bool measure_all = false;        // measure the folds' level on every ray they may bulge, touching or not
        // Centres of the neighbouring rings (fold-over limits), or null at an end.
        const Vec3* previous_centre = nullptr;
        const Vec3* next_centre = nullptr;
    };

    struct Result {
        bool touched = false;  // a ray was cut to a contact surface
        double lost_area = 0.0;   // of the weighted cross-section to the cut, m^2
        double bulge_reach = 0.0;  // w of the bulge (0: none)
        double short_area = 0.0;   // what the bulge could not give back, m^2
    };

    // Deforms the ring: free[j] is ray j's free radius t0 (m), out[j] receives its radius.
    // With no folds (folds empty) only the fold-over limits apply.
    Result deform(const FoldContacts& folds, const Ring& ring, const double* free, double* out);

    // After deform: the nearest fold's level o at ray j's free point, and its gradient (1/m);
    // at least (1 + kMaxBulgeReach) t_max / R_A (with a zero gradient) where no fold may
    // bring it lower or it was not measured (a ring that touches nothing, without
    // measure_all).
    double level(std::size_t j) const { return measured_ ? level_[j] : 1e30; }
    const Vec3& gradient(std::size_t j) const { return gradient_[j]; }
    const Vec3& direction(std::size_t j) const { return direction_[j]; }

private:
    // The level of the nearest other fold at p as seen from free radius t0 (x of
    // contact_profile.h), and its slope along the ray d.
    ContactRay measure(const FoldContacts& folds, const Ring& ring, const Vec3& p, const Vec3& d, double t0,
                       double u) const;
    // level_ and gradient_ of the nearest fold on every ray where a fold may come below
    // level `below` (o); true if a ray touches a fold (o R_A < t0).
    bool measure_levels(const FoldContacts& folds, const Ring& ring, const double* free, double t_max, double below);
    // The ring's weighted cross-section for radii t (Pappus), m^2.
    double section(const double* t) const;
    // Ray j's radius for a bulge of reach w (or its cut radius when it touches).
    double bulged(std::size_t j, double w) const;
    // t kept below ray j's fold-over limit.
    double limited(std::size_t j, double t) const;

    FoldContacts::Anchor anchors_[kMaxFolds];
    std::size_t folds_ = 0;
    bool measured_ = false;  // level_ and gradient_ hold the last ring's
    std::vector<Vec3> direction_;
    std::vector<double> wedge_;     // per ray: half the sine of the angle to the next ray
    std::vector<double> bend_;      // per ray: k . d_j
    std::vector<double> limit_;     // per ray: fold-over limit
    std::vector<double> free_;      // per ray: its free radius t0
    std::vector<double> cut_;       // per ray: after the contact cut
    std::vector<double> trial_;     // per ray: a bulge trial
    std::vector<double> level_;     // per ray: the nearest fold's level at t0 (o), ...
    std::vector<Vec3> gradient_;    // ... and its gradient
    std::vector<ContactRay> rays_;  // per ray: the folds' level near t0
    std::vector<uint32_t> bulging_;  // the free rays within the bulge's largest reach
};

}  // namespace enteron::skinning
