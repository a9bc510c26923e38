// SPDX-License-Identifier: Apache-2.0
// Distance surface of point skeletons (France et al. 2002, section 3), polygonised by
// marching cubes on a narrow band.
//
// Skeleton points lie on the axis evenly in arc length (their number follows the length,
// so stretching adds points instead of spreading them, and the radius does not pulse).
// Each contributes the compact kernel g(d) = (1 - d^2 / Rs^2)^3 weighted by the spacing,
// so the field is a Riemann sum of a line integral and does not depend on the spacing.
// Blending is limited to axis neighbours: a point of space sums only the skeleton points
// within D (the window) in arc length of its nearest skeleton point. Rs^2 = R^2 + D^2, so
// at the surface the window's edge contributes nothing and the field is continuous there.
// Beyond an end the field is made radial around the end point (a hemispherical cap), and
// points continue straight past the ends so the window is full up to them.
//
// One update, in four passes:
//  1. band: the lattice corners within R + 2 voxels of the axis (sparse blocks, see
//     sparse_voxel_grid.h), found by splatting spheres around every few skeleton points
//     (about one per R, the sphere grown to cover the points in between), each corner
//     keeping the nearest of them;
//  2. field: each band corner walks from that point to its nearest skeleton point along
//     the axis and sums the window there;
//  3. marching cubes on the band (marching_cubes.h);
//  4. each vertex is projected onto the iso-surface by Newton steps on the field until a
//     step is below R / 50; its normal is the field gradient of the last step and its u
//     the projection of the vertex on the axis next to its nearest skeleton point.
//
// A radius profile (tube_radius.h): a point p near skeleton point k takes the field at
// p stretched across the axis by R / r (r the radius at p's foot on the axis), so the
// surface lies at r from a straight axis and caps are hemispheres of the end's radius; the
// knobs (voxel, window, spacing) stay those of the largest radius R.
//
// Contacts: a point of space takes the field of its nearest skeleton point's window, so
// where two folds press into each other the field switches from one fold's to the
// other's on the plane half-way between their axes (the contact surface of equal radii),
// and the surface drawn is the two folds' union: their skins never pass through each
// other, and the shared contact surface lies inside the mesh, where nothing is drawn.
// What the union loses is the lens where the folds overlap; before the band's pass 2,
// rings of 16 rays every R / 2 along the skeleton (ring_contacts.h, free radius R) find
// the bulge reach w that gives each cross-section its area back, and the nearest fold's
// level on each ray. The field at p is then taken at c + (p - c) / (1 + D(x; w)), c the
// nearest skeleton point and x the fold's level at p interpolated from the four nearest
// rays' linear models (contact_profile.h): the surface swells by D around the contact,
// continuously in p, so marching cubes and the Newton steps see one smooth field.
#pragma once

#include <vector>

#include "skinning/axis_samples.h"
#include "skinning/bend_calibration.h"
#include "skinning/fold_contacts.h"
#include "skinning/marching_cubes.h"
#include "skinning/ring_contacts.h"
#include "skinning/rotation_minimizing_frames.h"
#include "skinning/skin.h"
#include "skinning/sparse_voxel_grid.h"

namespace enteron::skinning {

class PointSkeletonSkin final : public Skin {
public:
    explicit PointSkeletonSkin(const SkinSettings& settings);

    double iso_value() const { return iso_; }
    // Marching cubes make new triangles every update, whatever the settings.
    bool stable_topology() const override { return false; }
    bool rebuilds_whole_mesh() const override { return true; }
    std::size_t skeleton_points() const { return skeleton_.intervals() + 1; }
    // Field evaluations (window sums) of the last update: band corners and Newton steps.
    std::size_t last_field_evaluations() const { return evaluations_; }
    // The band of the last update, with the field at every corner (-1 outside the band).
    const SparseVoxelGrid& band() const { return grid_; }

private:
    void rebuild() override;
    // Field and gradient at p for the window around skeleton point k (an index into
    // skeleton_, real points only), with the bulge of the contacts or without.
    double field(Vec3 p, std::size_t k, Vec3* gradient, bool with_bulge = true) const;
    // The field marching cubes needs at a band corner: the bulge only where it may change
    // the corner's side.
    double band_field(const Vec3& p, std::size_t k) const;
    // The real skeleton point nearest to p, searching from k along the axis; *distance2
    // receives its squared distance to p.
    std::size_t nearest_from(Vec3 p, std::size_t k, double* distance2) const;
    // Sum of the window of skeleton point k at q (the field without the end caps) and,
    // with kGradient, its gradient.
    template <bool kGradient>
    float window_sum(float qx, float qy, float qz, std::size_t k, float* gradient) const;
    void load_skeleton();
    // The contact rings: their bulge reach and the folds' linear models per ray.
    void prepare_contacts();
    // D(x; w) at p near skeleton point k (0 without contacts or beyond the bulge), with
    // dD/dx in *slope and grad x in *gradient.
    double bulge_at(const Vec3& p, std::size_t k, double* slope, Vec3* gradient) const;
    // With a radius profile: R / r at p near skeleton point k, r the radius at p's foot on the
    // axis (linear between skeleton points, continuous where the nearest point changes).
    double stretch_at(const Vec3& p, std::size_t k) const;
    void splat();
    void evaluate_band();
    void project_vertices();

    double iso_ = 0.0;
    BendCalibration bend_;
    double support2_ = 0.0;  // Rs^2
    std::size_t window_points_ = 0;           // W: the window is skeleton points k - W .. k + W
    static constexpr std::size_t kLanes = 4;  // floats per SIMD register in the window sums
    std::size_t window_lanes_ = 0;            // 2 W + 1 rounded up to whole lane groups
    std::vector<float> window_mask_;          // 1 for the window's lanes, 0 past them
    std::size_t evaluations_ = 0;
    AxisSamples skeleton_;
    RotationMinimizingFrames frames_;  // along skeleton_, for the vertices' v
    std::size_t padding_ = 0;           // entries before skeleton point 0 in x_, y_, z_, excluded_
    std::vector<float> x_, y_, z_;      // skeleton positions, single precision, padded
    std::vector<float> excluded_;       // 0 at real skeleton points, huge at phantoms and padding
    std::vector<double> inverse_chord2_;  // 1 / |x_{j+1} - x_j|^2, m^-2
    std::vector<BendCalibration::Row> bend_rows_;  // per skeleton point: its curvature's row of bend_
    std::vector<Vec3> bend_axes_;         // per skeleton point: towards its centre of curvature, / R, 1/m
    std::vector<double> radii_;           // per skeleton point: the profile's radius there, m (empty without one)
    SparseVoxelGrid grid_;
    MarchingCubes cubes_;
    std::vector<int32_t> seeds_;  // per vertex: nearest skeleton point of its edge's inside corner

    // Contacts (empty without contact surfaces).
    static constexpr std::size_t kContactRays = 16;
    struct ContactRaySample {
        Vec3 point;     // the ray's point at R, m
        Vec3 gradient;  // of the nearest fold's level o there, 1/m
        double level;   // o there
    };
    FoldContacts folds_;
    RingContacts contacts_;
    std::size_t contact_stride_ = 1;              // skeleton points between two contact rings
    double bulge_floor_ = 0.0;                    // below this field no bulge reaches the iso-value
    std::vector<double> bulge_reach_;             // per contact ring: w
    std::vector<ContactRaySample> contact_rays_;  // per contact ring, kContactRays each
    std::vector<double> contact_cosine_, contact_sine_;
};

}  // namespace enteron::skinning
