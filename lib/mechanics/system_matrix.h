// SPDX-License-Identifier: Apache-2.0
// The implicit integrator's system matrix over the 3n coordinates x0 y0 z0 x1 y1 z1 ...
// A segment couples four consecutive control points (12 coordinates), so the half
// bandwidth is 3 * 3 + 2 = 11.
#pragma once

#include <cstddef>

#include "base/geometry.h"
#include "numerics/banded_matrix.h"
#include "spline/catmull_rom.h"
#include "spline/gram_matrix.h"

namespace enteron::mechanics {

using SystemMatrix = numerics::BandedSpdMatrix<11>;

// The stiffness of an axial force law at a spline point with unit direction u,
// H = a u u^T + b I (a spring, the stretch of the axis, an axial damper), acting through
// the weights w on q_first .. q_first+3: adds scale * (w w^T) (x) H to the system.
// The 12 coordinates of the four points are contiguous, so each row of the block is a
// contiguous run of the band: a rank-one update of g = w (x) u plus b on the diagonal
// coordinates.
void add_axial_block(SystemMatrix& system, const spline::SegmentWeights& weights, const Vec3& u, double a, double b,
                     double scale);

// The axial blocks of two spline points on the same four control points (the two Gauss
// nodes of a segment): the sum of two add_axial_block calls with a = a_k * scale and
// b = b_k * scale already multiplied out, in one pass over the band. A point that adds
// nothing (a degenerate direction) passes a = b = 0. Only the product a u u^T matters, so
// with b = 0 u need not be a unit vector (a d d^T / |d|^2 without the square root).
void add_axial_block_pair(SystemMatrix& system, const spline::SegmentWeights& weights0, const Vec3& u0, double a0,
                          double b0, const spline::SegmentWeights& weights1, const Vec3& u1, double a1, double b1);

// The blocks of several spline points on the same four control points, each with its own
// symmetric 3 x 3 matrix S_m (a point that sums several contacts): collects
// sum_m (w_m w_m^T) (x) S_m and adds it to the system once, instead of one pass over the
// band per contact.
class SegmentBlock {
public:
    // Starts an empty block on the control points first .. first+3.
    void reset(std::size_t first);
    std::size_t first() const { return first_; }
    // S given by its lower triangle: xx, yx, yy, zx, zy, zz.
    void add(const spline::SegmentWeights& weights, const double s[6]);
    void add_to(SystemMatrix& system) const;

private:
    std::size_t first_ = 0;
    double sums_[10][6] = {};  // point pairs (j, k <= j) by sums_[j (j + 1) / 2 + k]
};

// H x = a (u . x) u + b x for H = a u u^T + b I.
inline Vec3 axial_times(const Vec3& u, double a, double b, const Vec3& x) { return (a * u.dot(x)) * u + b * x; }

// out[first + k] += w_k f for the four points of a spline point: a force f at that point
// as generalised forces (3n vector). A tuned kernel, raw loops: the weights and f are
// copied first, so the compiler may assume that no store to `out` changes them (it
// reloaded both after every store, a third of a contact's cost).
inline void add_point_force(const spline::SegmentWeights& weights, const Vec3& f, double* out) {
    const double w[4] = {weights.w[0], weights.w[1], weights.w[2], weights.w[3]};
    const double g[3] = {f[0], f[1], f[2]};
    double* o = out + 3 * weights.first;
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) o[3 * k + c] += w[k] * g[c];
}

// add_point_force for two spline points on the same four control points (the two Gauss
// nodes of a segment): each coordinate of `out` is read and written once.
inline void add_point_force_pair(const spline::SegmentWeights& weights0, const Vec3& f0,
                                 const spline::SegmentWeights& weights1, const Vec3& f1, double* out) {
    const double w0[4] = {weights0.w[0], weights0.w[1], weights0.w[2], weights0.w[3]};
    const double w1[4] = {weights1.w[0], weights1.w[1], weights1.w[2], weights1.w[3]};
    const double g0[3] = {f0[0], f0[1], f0[2]}, g1[3] = {f1[0], f1[1], f1[2]};
    double* o = out + 3 * weights0.first;
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) o[3 * k + c] += w0[k] * g0[c] + w1[k] * g1[c];
}

}  // namespace enteron::mechanics

namespace enteron::mechanics {

// Adds scale * (B (x) I3) to the system: a per-coordinate matrix B (n x n, the same for
// x, y and z) such as the mass, bending or drag matrix.
void add_per_coordinate(const numerics::ScalarBandMatrix& b, double scale, SystemMatrix& system);

}  // namespace enteron::mechanics
