// SPDX-License-Identifier: Apache-2.0
// Convolution surface of the axis (France et al. 2002, section 4): the axis as a polyline of
// short segments, each contributing the closed-form 1/r^3 field of segment_kernel.h.
//
// Local convolution (Angelidis et al. 2002): a surface point attached to axis arc length u
// sums only the skeleton within [u - D, u + D] (D the window half-width, < 2R), clipped
// exactly at the window ends, so two folds of the bowel that touch never blend and the
// field slides smoothly with u. The axis is continued straight beyond its ends by D so
// the radius holds up to the ends; hemispherical caps close them.
//
// Seed-based polygonisation: every vertex has a fixed (ring, angle) on the ring grid and
// is solved along its ray from its ring centre, in the rotation-minimising frame, by
// safeguarded Newton iterations on the local field, starting from the radius it had in
// the previous frame (temporal coherence: usually one or two field evaluations). The
// iso-value is calibrated numerically at construction: the field of a straight skeleton
// at distance R, so a straight tube has radius exactly R. With a radius profile each ring's
// rays are solved stretched across the axis by R / r, r the ring's radius (the profile's at
// its place), so a straight tapered tube has radius exactly r(s) at each ring; the knobs
// (window, spacings) stay those of the largest radius R. The skeleton's points are evenly
// spaced, or (with a chord-error tolerance) closer where the axis bends, from
// skeleton_spacing on straight parts (ring_placement.h with a radius of 0). The level of detail is the number
// of segments around and the ring spacing: even, or (with a chord-error tolerance) closer
// where the axis bends, from ring_spacing on straight parts (ring_placement.h).
//
// Contacts: once every ring's free radii are solved (the rays, kept for the next frame's
// warm start), each ring is cut to the contact surfaces of the other folds, bulged to keep
// its cross-section and kept short of the neighbouring rings (ring_contacts.h); the caps'
// rows are cut to the contacts too (no bulge). Without contact surfaces only the fold-over
// limits apply.
#pragma once

#include <vector>

#include "skinning/axis_samples.h"
#include "skinning/bend_calibration.h"
#include "skinning/fold_contacts.h"
#include "skinning/ring_contacts.h"
#include "skinning/ring_grid.h"
#include "skinning/ring_placement.h"
#include "skinning/rotation_minimizing_frames.h"
#include "skinning/skin.h"

namespace enteron::skinning {

class ConvolutionSkin final : public Skin {
public:
    explicit ConvolutionSkin(const SkinSettings& settings);

    // The calibrated iso-value, 1/m^2.
    double iso_value() const { return iso_; }
    // Total field evaluations of the last update (for the benchmark's cost counters).
    std::size_t last_field_evaluations() const { return evaluations_; }
    // Rings of the last update cut to a contact surface.
    std::size_t last_touching_rings() const { return touching_rings_; }
    // Skeleton points (segment ends) of the last update on the axis, phantoms excluded.
    std::size_t skeleton_points() const { return skeleton_.intervals() + 1; }

private:
    void rebuild() override;
    // Gathers the clipped skeleton segments of the window around arc length s.
    void gather_window(double s);
    // The skeleton's spacing on a bend of curvature k (1/m): skeleton_spacing, or with a
    // curvature-following skeleton the spacing it takes there.
    double skeleton_spacing_for(double curvature) const;
    // The radius of body ring k, m: the profile's at its place (tube_radius.h), or R.
    double ring_radius(std::size_t k) const;
    double field(Vec3 p) const;
    // Distance along the ray from origin where the field crosses the iso-value.
    double solve_ray(Vec3 origin, Vec3 direction, double start, double iso);

    double iso_ = 0.0;
    BendCalibration bend_;
    AxisSamples skeleton_;
    std::size_t skeleton_intervals_ = 0;  // intervals of a curvature-following skeleton; 0 when even
    AxisSamples bends_;                   // even samples for placing a curvature-following skeleton
    RingPlacement skeleton_placement_;
    AxisSamples rings_;
    RotationMinimizingFrames frames_;
    RingGrid grid_;
    std::vector<Vec3> window_;               // segment end points, pairs
    RingPlacement placement_;
    std::vector<double> radius_, previous_;  // solved (free) ray length per (body ring, segment)
    std::vector<double> deformed_;           // after the contacts and fold-over limits, per (body ring, segment)
    std::vector<double> cap_free_, cap_deformed_;  // one cap row's rays
    FoldContacts folds_;
    RingContacts contacts_;
    std::size_t touching_rings_ = 0;
    std::vector<double> u_, previous_u_;     // arc length / length of each body ring
    std::size_t evaluations_ = 0;
};

}  // namespace enteron::skinning
