// SPDX-License-Identifier: Apache-2.0
// The other folds near a point of the bowel, and how far the point is from each, in units
// of that fold's radius: what contact_profile.h composes into contact surfaces.
//
// "Other" is everything of the axis but the point's own stretch of tube: the axis farther
// than the neighbour window along the same tube, or any point of another tube. The window
// is the mechanics' own (self_contact_force.h: pi R, where the tightest bend a tube can
// make brings two of its points 2R apart), entered smoothly: the normalised distance to a
// point of the same tube at arc length sigma from the query's own gets a penalty
//     kWindowPenalty (1 - smoothstep((sigma - 2 R) / (pi R - 2 R))),
// so nothing nearer than 2 R along the axis is ever another fold (the penalty puts it
// beyond any bulge), everything beyond pi R is one, and a part of the axis sliding across
// the window's edge changes the distance continuously (no popping). On a bend of radius
// >= R the own tube is never nearer than R to its own surface, so the window hides no
// contact a tube can make without folding over.
//
// The axis is a polyline of samples (the skin's skeleton: positions, curvature, arc
// length), each segment bowed by the curvature of its ends, q(l) = a + l (b - a) +
// l (1 - l) |b - a|^2 k / 2, so that a distance to it is within a few thousandths of the
// spline's at the skins' spacings (the chord alone is off by |b - a|^2 k / 8: 0.6 % R at a
// bend of radius 1.4 R with samples R / 4 apart). Both folds of a contact measure each
// other on the same polyline, so they see the same contact surface.
//
// Finding the folds: samples about 2 R apart along the axis ("coarse") are filed in a grid
// of cells as wide as the reach; each keeps, once per build, the other folds that may
// come within the bulge's reach of a query near it (one entry per pass of a fold: each
// coarse sample nearer than its neighbours along a run of consecutive ones, so that both
// legs of a U-turn passing by count). A query near arc length s takes the entries of the
// coarse sample nearest s and walks each along the polyline to the segment nearest the
// query point.
//
// Several tubes (the "intestines" issue): every sample carries its tube and radius, a
// segment never joins two tubes, and the window applies within a tube only. Today's skins
// build it from their one tube.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "base/geometry.h"
#include "skinning/axis_samples.h"
#include "skinning/tube_radius.h"

namespace enteron::skinning {

class FoldContacts {
public:
    static constexpr double kWindowPenalty = 4.0;  // added to o inside the own window: beyond any bulge

    // A fold near a query: the segment of its polyline nearest the query point, and the
    // query point's level there (o, penalty included).
    struct Anchor {
        uint32_t segment = 0;
        double level = 0.0;
    };

    // Rebuilds from the real samples of `axis` (one tube of radius `radius`, m, each sample
    // the radius `along` it when that varies, `radius` then its largest; bowed by its
    // curvature when computed), for queries up to `query_radius` (m) from the axis: the
    // folds are found as far as that plus the bulge's reach from the other fold's axis.
    // Allocates only when the samples grow.
    void build(const AxisSamples& axis, double radius, double query_radius, const TubeRadius& along = {});

    // The folds other than the own stretch of tube (tube `tube`, arc length `s`) that may
    // reach, with their bulge zone, a point within query_radius of `point` (a point of the
    // axis at arc length s), at most `max` of them, into `out`; their count.
    std::size_t near(const Vec3& point, uint32_t tube, double s, Anchor* out, std::size_t max) const;

    // o = r / R_F of the fold of `anchor` at p (r the distance to its bowed polyline, R_F its
    // radius), plus the window penalty for a point of the query's own tube (`tube`, `s`);
    // `gradient` receives grad o (of the distance term). Walks from the anchor's segment
    // (its estimate of the nearest segment moves by the projection of p on it).
    double level(const Vec3& p, uint32_t tube, double s, const Anchor& anchor, Vec3* gradient) const;

    // The radius of the fold of `anchor`, m.
    double radius(const Anchor& anchor) const { return radius_[anchor.segment]; }
    double reach() const { return reach_; }
    bool empty() const { return position_.empty(); }

private:
    struct SegmentPoint {
        Vec3 point;
        double arc;  // arc length of the point along its tube, m
    };
    // The point of segment i (samples i, i + 1) nearest to p (the bowed segment, foot
    // taken on the chord).
    SegmentPoint nearest_on_segment(const Vec3& p, std::size_t i) const;
    // o plus the window penalty for segment i, and its nearest point.
    double segment_level(const Vec3& p, uint32_t tube, double s, std::size_t i, SegmentPoint* nearest) const;
    // From segment i to the segment p projects onto (stepping while the foot falls beyond a
    // segment's end, but not into the own window of the query (tube, s); over a joint both
    // ends lie beyond, and the nearer of the two is taken). Its nearest point and squared
    // distance.
    std::size_t nearest_segment(const Vec3& p, uint32_t tube, double s, std::size_t i, SegmentPoint* nearest,
                                double* distance2) const;
    double window_penalty(uint32_t tube, double s, uint32_t other_tube, double other_s) const;
    bool is_segment(std::size_t i) const { return i + 1 < position_.size() && tube_[i] == tube_[i + 1]; }
    uint64_t cell_key(const Vec3& p) const;

    double query_radius_ = 0.0, reach_ = 0.0, window_start_ = 0.0, window_end_ = 0.0;
    // The samples of every tube, one after the other.
    std::vector<Vec3> position_;
    std::vector<Vec3> curvature_;  // dt/ds, 1/m
    std::vector<double> arc_;      // m, from the tube's first end
    std::vector<uint32_t> tube_;
    std::vector<double> radius_;   // m
    // Coarse samples: about R apart along each tube, and its last.
    std::vector<uint32_t> coarse_;                          // sample index of each
    std::vector<std::pair<uint64_t, uint32_t>> cells_;      // (cell key, coarse sample), sorted
    std::vector<uint32_t> folds_begin_;      // per coarse sample: its entries in folds_ (CSR)
    std::vector<uint32_t> folds_;            // sample index of the nearest coarse sample of each fold nearby
    std::vector<uint32_t> tube_first_coarse_;  // per tube: its first coarse sample
    std::vector<uint32_t> found_;            // build's work space
};

}  // namespace enteron::skinning
