// SPDX-License-Identifier: Apache-2.0
// The collision geometry of the bowel (France et al. 2002, section 2.2): spheres of the
// intestine radius R centred on the axis, evenly spaced in arc length. Their number is
// fixed when the scene is made (rest length / spacing), and each update spreads them over
// the current length, so the spacing stays even however the segments stretch.
//
// With a radius profile R(s) each sphere takes the radius at its place, and the spacing
// follows the radius: spacing x R(s) / R_max, so that the spheres overlap as much
// everywhere and a neighbour window counted in spheres (self_contact_force.h) spans the
// same multiple of the local radius. Their places are fixed in material arc length, as
// fractions of the length, and spread over the current length in those fractions.
//
// With several tubes (mechanics/axis_model.h) each tube has its spheres, one after the
// other in tube order, each knowing its tube; every contact effect sees them all.
//
// To stay cheap at 1 kHz the axis is followed as a fine polyline (a few samples per
// segment, whose basis weights are constant) and a sphere's centre and weights are
// interpolated on it; its force then reaches the control points through those weights.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "spline/catmull_rom.h"
#include "spline/gram_matrix.h"

namespace enteron::collision {

struct Sphere {
    spline::SegmentWeights weights;  // of the centre, on four control points
    Vec3 center = Vec3::Zero();      // m
    double arc_length;               // from the first end, m
    double radius = 0.0;             // m: the tube's there (constant, the profile's at rest)
    uint32_t tube = 0;               // which tube of the axis
};

// What the spheres of one tube are made from: its control points [first, first +
// control_points) of the state, its rest length (m), its spacing at rest (m), its radius (m,
// with a profile its largest value, `spacing` the spacing there), its spline's ends.
struct SphereTube {
    std::size_t first = 0;
    std::size_t control_points = 0;
    double rest_length = 0.0;
    double spacing = 0.0;
    double radius = 0.0;
    spline::Ends ends;
    const spline::LengthProfile* radius_profile = nullptr;
};

class CollisionSpheres {
public:
    // `spacing` (m) at rest; the count is round(rest_length / spacing) + 1. `ends`: the
    // spline's end treatment (the mechanics' own, AxisModel::ends). With a radius profile,
    // `radius` is its largest value and `spacing` the spacing there (see above).
    CollisionSpheres(std::size_t control_points, double rest_length, double spacing, double radius,
                     std::pmr::memory_resource* memory, spline::Ends ends = {},
                     const spline::LengthProfile* radius_profile = nullptr);
    // The spheres of several tubes, in their order, on a state of `control_points` points.
    CollisionSpheres(const std::vector<SphereTube>& tubes, std::size_t control_points,
                     std::pmr::memory_resource* memory);

    // Places the spheres on the axis given by the control points (x y z each). The effects
    // that make contacts share one set of spheres and each calls this for the state it
    // evaluates: only the first call for given control points does the work.
    void update(const double* control_points);
    // Counts the updates that moved the spheres: equal values, the same placement (lets an
    // effect reuse what it found for these spheres).
    uint64_t placement() const { return placement_; }

    // The velocities of the placed spheres' centres (x y z each, m/s) for the control
    // points' velocities v: worked out on the first call for this placement and these v,
    // then shared by the contact effects.
    const double* velocities(const double* v);

    std::size_t size() const { return spheres_.size(); }
    std::size_t control_points() const { return control_points_; }
    // Forgets the placement, so that the next update places the spheres anew (with the same
    // bits: a placement depends on the control points only) and counts a new placement: the
    // caches keyed on placements are dropped (after a restore).
    void forget_placement() { placed_ = false; }
    const Sphere& operator[](std::size_t i) const { return spheres_[i]; }
    // The largest sphere radius (every sphere's without a profile): what bounds and search
    // margins take; a contact takes each sphere's own (Sphere::radius).
    double radius() const { return radius_; }
    // The spacing at rest where the radius is radius() (everywhere without a profile): the
    // first tube's (tube_rest_spacing).
    double rest_spacing() const { return tubes_.front().rest_spacing; }
    // The tubes: how many, and for tube k its spheres [begin, end), its largest radius and
    // its spacing at rest where the radius is largest.
    std::size_t tube_count() const { return tubes_.size(); }
    std::size_t tube_begin(std::size_t tube) const { return tubes_[tube].sphere_begin; }
    std::size_t tube_end(std::size_t tube) const { return tubes_[tube].sphere_end; }
    double tube_radius(std::size_t tube) const { return tubes_[tube].radius; }
    double tube_rest_spacing(std::size_t tube) const { return tubes_[tube].rest_spacing; }

    // bound += scale * sum over spheres of w w^T (per coordinate): the stiffness bound of
    // a law of stiffness `scale` acting on every sphere at once.
    void add_weight_products(double scale, numerics::ScalarBandMatrix& bound) const;

private:
    static constexpr std::size_t kSamplesPerSegment = 4;  // polyline intervals per segment

    // A tube's samples [sample_begin, sample_end) and spheres [sphere_begin, sphere_end).
    struct TubeSpheres {
        std::size_t sample_begin = 0, sample_end = 0;
        std::size_t sphere_begin = 0, sphere_end = 0;
        double radius = 0.0;        // m, the largest
        double rest_spacing = 0.0;  // m, where the radius is largest
        bool profiled = false;      // spheres at rest_fractions_ (a radius profile)
    };
    void add_tube(const SphereTube& tube);
    void place_tube(const TubeSpheres& tube, const double* control_points);

    std::size_t control_points_;
    double radius_;
    std::pmr::vector<TubeSpheres> tubes_;
    std::pmr::vector<spline::SegmentWeights> sample_weights_;  // (kSamples + 1) per segment
    std::pmr::vector<double> sample_points_;                   // x y z per sample
    std::pmr::vector<double> sample_arc_;                      // arc length at each sample
    std::pmr::vector<Sphere> spheres_;
    std::pmr::vector<double> rest_fractions_;  // each sphere's arc length / its tube's length (profiled tubes)
    std::pmr::vector<double> placed_for_;  // the control points of the last update
    std::pmr::vector<double> velocities_;  // of the centres, x y z
    std::pmr::vector<double> velocities_for_;  // the control point velocities they are for
    uint64_t velocities_placement_ = 0;        // and the placement (0: none yet)
    bool placed_ = false;
    uint64_t placement_ = 0;
};

}  // namespace enteron::collision
