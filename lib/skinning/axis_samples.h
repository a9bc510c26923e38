// SPDX-License-Identifier: Apache-2.0
// The axis sampled evenly in arc length: the common input of every skin. Positions and
// unit tangents come from the spline itself (not a polyline), so a ring or a skeleton
// point sits exactly on the axis. Optionally the samples continue beyond both ends along
// each end's osculating circle (straight where the end does not bend; "phantom" samples),
// so that a local window near an end sees as much skeleton, bent as much, as in the middle
// and the radius does not change there.
#pragma once

#include <cstddef>
#include <vector>

#include "base/geometry.h"
#include "spline/arc_length.h"

namespace enteron::skinning {

class AxisSamples {
public:
    // What the samples carry besides positions and tangents.
    enum class Curvature : bool { skip = false, compute = true };

    // Samples the spline of `count` control points (x y z each) at `intervals` (>= 1) equal
    // steps of arc length, plus ceil(extension / step) phantom samples beyond each end.
    // Allocates only when the sample count grows.
    void build(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
               std::size_t intervals, double extension, Curvature curvature);
    // The intervals whose step is closest to `spacing` along `length` (both m), at least 1.
    static std::size_t intervals_for(double length, double spacing);

    // Samples the spline at the given arc lengths (increasing, from 0 to the total length),
    // e.g. rings or skeleton points placed closer where the axis bends (ring_placement.h),
    // with phantoms over `extension` beyond each end at that end's own spacing.
    void build_at(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                  const std::vector<double>& arc_lengths, Curvature curvature, double extension = 0.0);

    std::size_t size() const { return position_.size(); }  // all samples, phantoms included
    std::size_t phantoms() const { return phantoms_; }        // phantom samples before (and after) the axis
    std::size_t intervals() const { return intervals_; }      // real samples - 1
    double spacing() const { return spacing_; }               // actual arc length between samples (mean if uneven), m
    double length() const { return length_; }                 // total arc length, m
    // Arc length of sample i from the first end (negative for the leading phantoms), m.
    double arc_length(std::size_t i) const {
        return arc_.empty() ? (double(i) - double(phantoms_)) * spacing_ : arc_[i];
    }
    // The same over the length, [0, 1] on the axis: exactly (i - phantoms) / intervals when
    // even, so that it does not change while the axis stretches.
    double fraction(std::size_t i) const {
        if (!arc_.empty()) return length_ > 0.0 ? arc_[i] / length_ : 0.0;
        return (double(i) - double(phantoms_)) / double(intervals_);
    }

    const Vec3& position(std::size_t i) const { return position_[i]; }
    // The spline parameter of sample i (0 .. count - 1; a phantom takes its end's): where the
    // sample lies on the material axis, for the radius there (tube_radius.h).
    double parameter(std::size_t i) const { return parameter_[i]; }
    const Vec3& tangent(std::size_t i) const { return tangent_[i]; }
    // Curvature vector dt/ds of sample i (towards the centre of curvature, length 1 / radius
    // of curvature), 1/m; the phantoms' that of their end. Only if built with
    // Curvature::compute.
    const Vec3& curvature(std::size_t i) const { return curvature_[i]; }
    bool has_curvature() const { return !position_.empty() && curvature_.size() == position_.size(); }

    // The unit tangent at arc length s (interpolated between samples, normalised), and the
    // mean bend of the axis over [s - half, s + half]: its turning angle over 2 half, in
    // the direction of t(s + half) - t(s - half), 1/m. Exact on an arc (the turning angle
    // from the chord of the tangents, 2 asin(|dt| / 2)); the mean curvature elsewhere.
    // Unlike the curvature at a point, it is continuous in s where the spline's curvature
    // jumps (at its control points, C1 but not C2): a ring sliding across one sees the
    // bend change gradually. (s +- half within the samples, phantoms included.)
    Vec3 tangent_at(double s) const;
    Vec3 mean_bend(double s, double half) const;

private:
    // Positions and tangents of the real samples k = 0 .. intervals_, at arc_length_of(k).
    template <typename ArcLengthOf>
    void sample(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                ArcLengthOf arc_length_of, Curvature curvature);

    // The phantoms beyond each end (phantoms_ of them), at each end's spacing.
    void extend_ends(const double* points_xyz, std::size_t count, double first_spacing, double last_spacing,
                     Curvature curvature);
    // dt/ds of the spline at parameter s, from its first derivative d there and t = d / |d|.
    static Vec3 curvature_vector(const double* points_xyz, std::size_t count, double s, const Vec3& d,
                                 const Vec3& t);

    std::vector<Vec3> position_;
    std::vector<Vec3> tangent_;
    std::vector<Vec3> curvature_;
    std::vector<double> parameter_;
    std::vector<double> arc_;  // arc length of each sample (phantoms included) when uneven (build_at), else empty
    std::size_t phantoms_ = 0;
    std::size_t intervals_ = 0;
    double spacing_ = 0.0;
    double length_ = 0.0;
};

}  // namespace enteron::skinning
