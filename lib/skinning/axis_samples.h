// The axis sampled evenly in arc length: the common input of every skin. Positions and
// unit tangents come from the spline itself (not a polyline), so a ring or a skeleton
// point sits exactly on the axis. Optionally the samples continue straight beyond both
// ends along the end tangents ("phantom" samples), so that a local window near an end sees
// as much skeleton as in the middle and the radius does not shrink there.
#pragma once

#include <cstddef>
#include <vector>

#include "skinning/vec3.h"
#include "spline/arc_length.h"

namespace enteron::skinning {

class AxisSamples {
public:
    // Samples the spline of `count` control points (x y z each) with a spacing as close to
    // `spacing` as divides the length evenly, plus ceil(extension / spacing) phantom
    // samples beyond each end. Allocates only when the sample count grows.
    void build(const spline::ArcLengthTable& table, const double* points_xyz, std::size_t count, double spacing,
               double extension);

    std::size_t size() const { return position_.size(); }  // all samples, phantoms included
    std::size_t phantoms() const { return phantoms_; }        // phantom samples before (and after) the axis
    std::size_t intervals() const { return intervals_; }      // real samples - 1
    double spacing() const { return spacing_; }               // actual arc length between samples, m
    double length() const { return length_; }                 // total arc length, m
    // Arc length of sample i from the first end (negative for the leading phantoms), m.
    double arc_length(std::size_t i) const { return (double(i) - double(phantoms_)) * spacing_; }

    const Vec3& position(std::size_t i) const { return position_[i]; }
    const Vec3& tangent(std::size_t i) const { return tangent_[i]; }

private:
    std::vector<Vec3> position_;
    std::vector<Vec3> tangent_;
    std::size_t phantoms_ = 0;
    std::size_t intervals_ = 0;
    double spacing_ = 0.0;
    double length_ = 0.0;
};

}  // namespace enteron::skinning
