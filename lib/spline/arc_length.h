// SPDX-License-Identifier: Apache-2.0
// Arc length along the spline, and its inverse: where along the axis is the point that
// lies a given distance from the first end. Used to sample the axis evenly in arc length
// (ent_scene_axis, skins, the accuracy study), whatever the stretch of each segment.
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "spline/catmull_rom.h"

namespace enteron::spline {

class ArcLengthTable {
public:
    explicit ArcLengthTable(std::pmr::memory_resource* memory = std::pmr::get_default_resource())
        : cumulative_(memory) {}

    // Builds the table for `count` control points (x y z each) and the end treatment `ends`.
    // Allocates only when the count grows.
    void build(const double* points_xyz, std::size_t count, Ends ends = {});

    // Total arc length of the axis, m.
    double total_length() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }

    // Global spline parameter s in [0, count-1] at arc length `length` from the first end
    // (clamped to [0, total]). Accurate to about 1e-12 of a segment.
    double parameter_at(double length) const;

    // Arc length from the first end to parameter s.
    double length_at(double s) const;

    // Samples `samples` points evenly in arc length, first end to last (samples >= 2),
    // into out_xyz (samples x 3).
    void sample_evenly(std::size_t samples, double* out_xyz) const;

private:
    double speed(double s) const;                    // |dP/ds| at global parameter s
    double integrate(double s0, double s1) const;    // arc length between two parameters

    const double* points_ = nullptr;
    std::size_t count_ = 0;
    Ends ends_;
    std::pmr::vector<double> cumulative_;  // length at s = k / 8 (8 intervals per segment)
};

// The most stretched segment of the axis (between two consecutive control points): its
// stretch, arc length over `rest_segment_length` minus 1, and the arc-length fraction u in
// [0, 1] of its middle. One pass over the axis, no allocation (a reader thread's query).
struct SegmentStretch {
    double stretch = 0.0;
    double u = 0.0;
};
SegmentStretch largest_segment_stretch(const double* points_xyz, std::size_t count, double rest_segment_length,
                                       Ends ends = {});

// Samples `samples` points (>= 2) evenly in arc length without a table: two passes over
// the axis, no allocation (what a reader thread wants for a one-off query).
void sample_evenly(const double* points_xyz, std::size_t count, std::size_t samples, double* out_xyz, Ends ends = {});

}  // namespace enteron::spline
