// SPDX-License-Identifier: Apache-2.0
// Which sight lines the bowel hides, and where: the geometry of ent_scene_exposure.
//
// The bowel's surface is the union of spheres swept along each tube's axis at the local
// radius (the surface the skins draw and the contacts keep apart). Each tube's axis is
// given as a polyline of samples a_i with a radius r_i each, so chord i, from a_i to
// a_{i+1}, is a round cone whose radius goes linearly from r_i to r_{i+1}. A sight line
// from the eye e to a target point p is hidden by chord i when the two segments come
// closer than the radius there:
//     |P(s) - A_i(t)| < r_i + t (r_{i+1} - r_i)   at their closest points (s, t)
// (exact for a constant radius; where the radius changes along a chord, the closest
// points of the two axes stand in for the closest approach to the cone, off by at most
// the radius' change over one chord).
//
// Cost: the chords are grouped in runs of kRunChords, each with a bounding sphere, so a
// sight line is tested against every run's sphere and only against the chords of the runs
// it passes through.
//
// A measure makes three passes: (1) every sight line against the chords near it: hidden or
// not, which chords hide something, and the first chord of each run of consecutive chords
// the line crosses (up to kRunsPerLine of them); (2) runs of hiding chords become spans,
// those less than one local diameter apart along the bowel merged (one loop is one span);
// (3) each hidden sight line adds its weight once to every span its runs lie in (a line
// that crossed more runs than it kept is traced again).
// Every buffer is sized by reserve(): a measure allocates nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/geometry.h"

namespace enteron::collision {

// A run of the bowel that hides part of the target.
struct OccludingSpan {
    int32_t tube = 0;
    double u_first = 0.0;  // where the run starts along its tube, arc length fraction in [0, 1]
    double u_last = 0.0;   // where it ends
    double hidden_weight = 0.0;  // the weight of the sight lines it crosses
};

struct OcclusionTotals {
    double total_weight = 0.0;
    double visible_weight = 0.0;
    std::size_t hidden_lines = 0;
};

class TubeOcclusion {
public:
    static constexpr std::size_t kRunsPerLine = 8;

    // Adds a tube of `samples` (>= 2) axis samples, their radii given (m), its chords tested
    // in runs of `chords_per_run` behind one bounding sphere. Allocates; the positions are set
    // before each measure through positions().
    void add_tube(int32_t tube, const double* radii, std::size_t samples, std::size_t chords_per_run);
    // Makes room for measures of up to `sight_lines` sight lines: none allocates after.
    void reserve_sight_lines(std::size_t sight_lines);

    std::size_t tubes() const { return tubes_.size(); }
    std::size_t samples(std::size_t tube) const { return tubes_[tube].samples; }
    // Where tube k's sample positions go (samples x 3, m), before prepare().
    double* positions(std::size_t tube) { return positions_[tubes_[tube].first].data(); }

    // After the positions are in: each sample's arc length fraction along its tube and the
    // runs' bounding spheres.
    void prepare();

    // The sight lines from `eye` to each target point (count x 3, m), weighted (count
    // weights >= 0). Fills spans() and hidden(); returns the totals.
    OcclusionTotals measure(const Vec3& eye, const double* targets_xyz, const double* weights, std::size_t count);

    const std::vector<OccludingSpan>& spans() const { return spans_; }
    bool hidden(std::size_t line) const { return line_hidden_[line] != 0; }

private:
    struct Tube {
        int32_t id;
        std::size_t first;    // its first sample
        std::size_t samples;
        double length = 0.0;  // m, of its polyline
    };
    struct Run {
        std::size_t first;   // its first chord (the index of the chord's first sample)
        std::size_t chords;
        std::size_t tube;
        Vec3 center = Vec3::Zero();
        double radius = 0.0;  // m: every chord's cone lies within
    };

    // Calls hide(chord) for every chord whose cone the segment eye-target passes through, in
    // increasing chord order.
    template <class Hide>
    void for_each_hiding_chord(const Vec3& eye, const Vec3& target, Hide&& hide) const;
    // Pass 2: spans from the hiding chords.
    void make_spans();

    std::vector<Tube> tubes_;
    std::vector<Run> runs_;
    // Per sample (the polyline's vertex i, and chord i from it to i + 1 within its tube):
    std::vector<Vec3> positions_;  // packed: Vec3 is three doubles, so data() is x y z per sample
    std::vector<double> radii_;
    std::vector<double> u_;
    std::vector<uint8_t> chord_hides_;
    std::vector<int32_t> chord_span_;
    // Per sight line:
    std::vector<uint8_t> line_hidden_;
    std::vector<uint8_t> line_runs_;           // runs of hiding chords kept; kRunsPerLine + 1: more
    std::vector<uint32_t> line_run_chords_;    // kRunsPerLine per line: the first chord of each run
    std::vector<OccludingSpan> spans_;  // reserved to the most spans the chords allow
};

}  // namespace enteron::collision
