// SPDX-License-Identifier: Apache-2.0
#include "collision/tube_occlusion.h"

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "base/segment_distance.h"

namespace enteron::collision {

namespace {

// |x - segment(a, b)|^2: how near a run's centre the sight line passes.
double distance_squared_to_segment(const Vec3& x, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((x - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (a + t * ab - x).squaredNorm();
}

}  // namespace

void TubeOcclusion::add_tube(int32_t tube, const double* radii, std::size_t samples, std::size_t chords_per_run) {
    if (samples < 2) throw Error(ErrorCode::internal, "a tube needs two axis samples");
    const std::size_t first = positions_.size();
    tubes_.push_back({tube, first, samples});
    positions_.resize(first + samples, Vec3::Zero());
    radii_.insert(radii_.end(), radii, radii + samples);
    u_.resize(first + samples, 0.0);
    chord_hides_.resize(first + samples, 0);
    chord_span_.resize(first + samples, -1);
    chords_per_run = std::max<std::size_t>(chords_per_run, 1);
    for (std::size_t chord = 0; chord + 1 < samples; chord += chords_per_run)
        runs_.push_back({first + chord, std::min(chords_per_run, samples - 1 - chord), tubes_.size() - 1});
    // At most one span per two chords (a span and a gap), plus one per tube.
    spans_.reserve(positions_.size() / 2 + tubes_.size());
}

void TubeOcclusion::reserve_sight_lines(std::size_t sight_lines) {
    line_hidden_.resize(sight_lines, 0);
    line_runs_.resize(sight_lines, 0);
    line_run_chords_.resize(sight_lines * kRunsPerLine, 0);
}

void TubeOcclusion::prepare() {
    for (Tube& tube : tubes_) {
        // Arc length fractions along the polyline (as the contacts' u, on theirs).
        double length = 0.0;
        u_[tube.first] = 0.0;
        for (std::size_t i = tube.first + 1; i < tube.first + tube.samples; ++i) {
            length += (positions_[i] - positions_[i - 1]).norm();
            u_[i] = length;
        }
        tube.length = length;
        const double inverse = length > 0.0 ? 1.0 / length : 0.0;
        for (std::size_t i = tube.first; i < tube.first + tube.samples; ++i) u_[i] *= inverse;
    }
    for (Run& run : runs_) {
        Vec3 low = positions_[run.first], high = low;
        double largest_radius = 0.0;
        for (std::size_t i = run.first; i <= run.first + run.chords; ++i) {
            low = low.cwiseMin(positions_[i]);
            high = high.cwiseMax(positions_[i]);
            largest_radius = std::max(largest_radius, radii_[i]);
        }
        run.center = 0.5 * (low + high);
        double farthest2 = 0.0;
        for (std::size_t i = run.first; i <= run.first + run.chords; ++i)
            farthest2 = std::max(farthest2, (positions_[i] - run.center).squaredNorm());
        run.radius = std::sqrt(farthest2) + largest_radius;
    }
}

template <class Hide>
void TubeOcclusion::for_each_hiding_chord(const Vec3& eye, const Vec3& target, Hide&& hide) const {
    for (const Run& run : runs_) {
        if (distance_squared_to_segment(run.center, eye, target) >= run.radius * run.radius) continue;
        for (std::size_t i = run.first; i < run.first + run.chords; ++i) {
            const SegmentClosest c = closest_points_of_segments(eye, target, positions_[i], positions_[i + 1]);
            const double radius = radii_[i] + c.t * (radii_[i + 1] - radii_[i]);
            if (c.distance_squared < radius * radius) hide(i);
        }
    }
}

OcclusionTotals TubeOcclusion::measure(const Vec3& eye, const double* targets_xyz, const double* weights,
                                       std::size_t count) {
    if (count > line_hidden_.size()) throw Error(ErrorCode::internal, "more sight lines than reserved");
    std::fill(chord_hides_.begin(), chord_hides_.end(), 0);
    OcclusionTotals totals;
    // Pass 1: which sight lines are hidden, which chords hide, and the runs each line crosses.
    for (std::size_t line = 0; line < count; ++line) {
        std::size_t runs = 0, last_chord = 0;
        uint32_t* run_chords = &line_run_chords_[line * kRunsPerLine];
        for_each_hiding_chord(eye, point_at(targets_xyz, line), [&](std::size_t chord) {
            chord_hides_[chord] = 1;
            if (runs == 0 || chord != last_chord + 1) {
                if (runs < kRunsPerLine) run_chords[runs] = static_cast<uint32_t>(chord);
                runs = std::min(runs + 1, kRunsPerLine + 1);
            }
            last_chord = chord;
        });
        line_runs_[line] = static_cast<uint8_t>(runs);
        line_hidden_[line] = runs > 0 ? 1 : 0;
        totals.total_weight += weights[line];
        if (runs > 0) {
            totals.hidden_lines += 1;
        } else {
            totals.visible_weight += weights[line];
        }
    }
    make_spans();
    // Pass 3: each hidden sight line adds its weight once to every span it crosses (its runs
    // come in increasing chord order, and so do their spans; consecutive hiding chords are
    // always in one span).
    for (std::size_t line = 0; line < count; ++line) {
        if (line_hidden_[line] == 0) continue;
        int32_t last = -1;
        auto add = [&](std::size_t chord) {
            const int32_t span = chord_span_[chord];
            if (span == last) return;
            spans_[static_cast<std::size_t>(span)].hidden_weight += weights[line];
            last = span;
        };
        if (line_runs_[line] <= kRunsPerLine) {
            for (std::size_t r = 0; r < line_runs_[line]; ++r) add(line_run_chords_[line * kRunsPerLine + r]);
        } else {
            for_each_hiding_chord(eye, point_at(targets_xyz, line), add);
        }
    }
    return totals;
}

void TubeOcclusion::make_spans() {
    spans_.clear();  // keeps the capacity reserved by add_tube
    for (const Tube& tube : tubes_) {
        int32_t open = -1;          // the span being extended, if any
        std::size_t last_hiding = 0;  // its last hiding chord
        for (std::size_t i = tube.first; i + 1 < tube.first + tube.samples; ++i) {
            chord_span_[i] = -1;
            if (chord_hides_[i] == 0) continue;
            // Runs less than one local diameter apart along the bowel are one loop.
            const double gap = (u_[i] - u_[last_hiding + 1]) * tube.length;
            if (open >= 0 && gap < 2.0 * std::max(radii_[i], radii_[last_hiding])) {
                for (std::size_t k = last_hiding + 1; k <= i; ++k) chord_span_[k] = open;
            } else {
                open = static_cast<int32_t>(spans_.size());
                spans_.push_back({tube.id, u_[i], 0.0, 0.0});
                chord_span_[i] = open;
            }
            spans_[static_cast<std::size_t>(open)].u_last = u_[i + 1];
            last_hiding = i;
        }
    }
}

}  // namespace enteron::collision
