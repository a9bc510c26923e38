// The axis sampled evenly in arc length: the common input of every skin. Positions and
// unit tangents come from the spline itself (not a polyline), so a ring or a skeleton
// point sits exactly on the axis. Optionally the samples continue straight beyond both
// ends along the end tangents ("phantom" samples), so that a local window near an end sees
// as much skeleton as in the middle and the radius does not shrink there.
#pragma once

#include <cstddef>
#include <vector>

#include "base/geometry.h"
#include "spline/arc_length.h"

namespace enteron::skinning {

class AxisSamples {
public:
    // Samples the spline of `count` control points (x y z each) with a spacing as close to
    // `spacing` as divides the length evenly, plus ceil(extension / spacing) phantom
    // samples beyond each end. Allocates only when the sample count grows.
    void build(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count, double spacing,
               double extension);

    // Samples the spline at the given arc lengths (increasing, from 0 to the total length;
    // no phantoms), e.g. rings placed closer where the axis bends (ring_placement.h).
    void build_at(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                  const std::vector<double>& arc_lengths);

    std::size_t size() const { return position_.size(); }  // all samples, phantoms included
    std::size_t phantoms() const { return phantoms_; }        // phantom samples before (and after) the axis
    std::size_t intervals() const { return intervals_; }      // real samples - 1
    double spacing() const { return spacing_; }               // actual arc length between samples (mean if uneven), m
    double length() const { return length_; }                 // total arc length, m
    // Arc length of sample i from the first end (negative for the leading phantoms), m.
    double arc_length(std::size_t i) const {
        return arc_.empty() ? (double(i) - double(phantoms_)) * spacing_ : arc_[i];
    }

    const Vec3& position(std::size_t i) const { return position_[i]; }
    const Vec3& tangent(std::size_t i) const { return tangent_[i]; }

private:
    // Positions and tangents of the real samples k = 0 .. intervals_, at arc_length_of(k).
    template <typename ArcLengthOf>
    void sample(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count,
                ArcLengthOf arc_length_of);

    std::vector<Vec3> position_;
    std::vector<Vec3> tangent_;
    std::vector<double> arc_;  // arc length of each sample when uneven (build_at), else empty
    std::size_t phantoms_ = 0;
    std::size_t intervals_ = 0;
    double spacing_ = 0.0;
    double length_ = 0.0;
};

}  // namespace enteron::skinning
