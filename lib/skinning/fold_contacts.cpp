// SPDX-License-Identifier: Apache-2.0
#include "skinning/fold_contacts.h"

#include <algorithm>
#include <cmath>

#include "skinning/contact_profile.h"
#include "skinning/frame_buffers.h"

namespace enteron::skinning {

namespace {

// Coarse samples about this far apart along the axis, in radii (a query walks at most
// half of it along a fold).
constexpr double kCoarseSpacingRadii = 2.0;

double smoothstep(double z) { return z * z * (3.0 - 2.0 * z); }

}  // namespace

uint64_t FoldContacts::cell_key(const Vec3& p) const {
    const auto pack = [&](double x) {
        return uint64_t(int64_t(std::floor(x / reach_)) + (int64_t(1) << 20)) & 0x1fffffULL;
    };
    return (pack(p.x()) << 42) | (pack(p.y()) << 21) | pack(p.z());
}

[[gnu::always_inline]] inline double FoldContacts::window_penalty(uint32_t tube, double s, uint32_t other_tube,
                                                                   double other_s) const {
    if (tube != other_tube) return 0.0;
    const double sigma = std::fabs(other_s - s);
    if (sigma >= window_end_) return 0.0;
    if (sigma <= window_start_) return kWindowPenalty;
    return kWindowPenalty * (1.0 - smoothstep((sigma - window_start_) / (window_end_ - window_start_)));
}

[[gnu::always_inline]] inline FoldContacts::SegmentPoint FoldContacts::nearest_on_segment(const Vec3& p, std::size_t i) const {
    const Vec3& a = position_[i];
    const Vec3 e = position_[i + 1] - a;
    const double length2 = e.squaredNorm();
    const double l = length2 > 0.0 ? std::clamp((p - a).dot(e) / length2, 0.0, 1.0) : 0.0;
    // The spline runs outside its chord, away from the centre of curvature, by l (1 - l)
    // |e|^2 k / 2.
    const Vec3 bow = (0.25 * l * (1.0 - l) * length2) * (curvature_[i] + curvature_[i + 1]);
    return {a + l * e - bow, arc_[i] + l * (arc_[i + 1] - arc_[i])};
}

[[gnu::always_inline]] inline double FoldContacts::segment_level(const Vec3& p, uint32_t tube, double s, std::size_t i,
                                                                   SegmentPoint* nearest) const {
    *nearest = nearest_on_segment(p, i);
    return (p - nearest->point).norm() / radius_[i] + window_penalty(tube, s, tube_[i], nearest->arc);
}

void FoldContacts::build(const AxisSamples& axis, double radius, double query_radius, const TubeRadius& along) {
    query_radius_ = query_radius;
    reach_ = query_radius + radius * (1.0 + kMaxBulgeReach);
    window_start_ = 2.0 * radius;
    window_end_ = kPi * radius;
    const std::size_t first = axis.phantoms(), n = axis.intervals() + 1;
    resize_buffer(position_, n);
    resize_buffer(curvature_, n);
    resize_buffer(arc_, n);
    assign_buffer(tube_, n, uint32_t{0});
    assign_buffer(radius_, n, radius);
    const bool has_curvature = axis.has_curvature();
    for (std::size_t i = 0; i < n; ++i) {
        position_[i] = axis.position(first + i);
        curvature_[i] = has_curvature ? axis.curvature(first + i) : Vec3::Zero();
        arc_[i] = axis.arc_length(first + i);
        if (along.varies()) radius_[i] = along.at_parameter(axis.parameter(first + i), radius);
    }
    // Coarse samples about kCoarseSpacingRadii apart in arc length, and each end.
    coarse_.clear();
    reserve_with_headroom(coarse_, n);
    double next = -1.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (arc_[i] >= next || i + 1 == n) {
            coarse_.push_back(uint32_t(i));
            next = arc_[i] + kCoarseSpacingRadii * radius_[i];
        }
    }
    assign_buffer(tube_first_coarse_, std::size_t{2}, uint32_t{0});
    tube_first_coarse_[1] = uint32_t(coarse_.size());
    double coarse_gap = 0.0;  // the longest arc between two coarse samples
    for (std::size_t k = 0; k + 1 < coarse_.size(); ++k)
        coarse_gap = std::max(coarse_gap, arc_[coarse_[k + 1]] - arc_[coarse_[k]]);

    // The grid: coarse samples sorted by cell.
    resize_buffer(cells_, coarse_.size());
    for (std::size_t k = 0; k < coarse_.size(); ++k) cells_[k] = {cell_key(position_[coarse_[k]]), uint32_t(k)};
    std::sort(cells_.begin(), cells_.end());

    // Per coarse sample, the folds that may come within the bulge's reach of a query made
    // within query_radius of a point of the axis nearer to it than to the next coarse
    // sample: a lower bound of o over such pairs below 1 + kMaxBulgeReach.
    const double threshold = 1.0 + kMaxBulgeReach;
    double largest_radius = 0.0;
    for (double r : radius_) largest_radius = std::max(largest_radius, r);
    const double farthest = threshold * largest_radius + coarse_gap + query_radius_;  // no fold beyond
    resize_buffer(folds_begin_, coarse_.size() + 1);
    folds_.clear();
    for (std::size_t k = 0; k < coarse_.size(); ++k) {
        folds_begin_[k] = uint32_t(folds_.size());
        const std::size_t ik = coarse_[k];
        const Vec3& pk = position_[ik];
        found_.clear();
        const uint64_t key = cell_key(pk);
        for (int64_t dz = -1; dz <= 1; ++dz)
            for (int64_t dy = -1; dy <= 1; ++dy) {
                // The three cells along x are consecutive keys.
                const uint64_t row = key + (uint64_t(dy) << 21) + (uint64_t(dz) << 42);
                auto it = std::lower_bound(cells_.begin(), cells_.end(), std::pair<uint64_t, uint32_t>{row - 1, 0});
                for (; it != cells_.end() && it->first <= row + 1; ++it) {
                    const std::size_t j = it->second, ij = coarse_[j];
                    const double distance2 = (position_[ij] - pk).squaredNorm();
                    if (j == k || distance2 > farthest * farthest) continue;
                    const double gap = std::max(0.0, std::sqrt(distance2) - coarse_gap - query_radius_);
                    const double sigma = std::fabs(arc_[ij] - arc_[ik]) + coarse_gap;
                    const double lower = gap / radius_[ij] + window_penalty(tube_[ik], arc_[ik], tube_[ij], sigma + arc_[ik]);
                    if (lower < threshold) found_.push_back(uint32_t(j));
                }
            }
        std::sort(found_.begin(), found_.end());
        // One entry per pass of a fold: each local minimum, along a run of consecutive coarse
        // samples of one tube, of the level pk sees there (distance and window penalty: a
        // run may hold both legs of a U-turn, and the bend between them within the window).
        for (std::size_t a = 0; a < found_.size();) {
            std::size_t b = a + 1;
            while (b < found_.size() && found_[b] == found_[b - 1] + 1 && tube_[coarse_[found_[b]]] == tube_[coarse_[found_[a]]])
                ++b;
            const auto level = [&](std::size_t f) {
                const std::size_t j = coarse_[found_[f]];
                return (position_[j] - pk).norm() / radius_[j] + window_penalty(tube_[ik], arc_[ik], tube_[j], arc_[j]);
            };
            for (std::size_t f = a; f < b; ++f) {
                const double here = level(f);
                if ((f == a || here <= level(f - 1)) && (f + 1 == b || here < level(f + 1))) folds_.push_back(coarse_[found_[f]]);
            }
            a = b;
        }
    }
    folds_begin_[coarse_.size()] = uint32_t(folds_.size());
}

std::size_t FoldContacts::nearest_segment(const Vec3& p, uint32_t tube, double s, std::size_t i, SegmentPoint* nearest,
                                          double* distance2) const {
    // Never into the query's own stretch of tube: that is not this fold.
    const auto own = [&](std::size_t j) { return tube_[j] == tube && std::fabs(arc_[j] - s) < window_start_; };
    int last_step = 0;
    for (int steps = 0; steps < 64; ++steps) {
        const Vec3 e = position_[i + 1] - position_[i];
        const double along = (p - position_[i]).dot(e);
        int step = 0;
        if (along < 0.0 && i > 0 && is_segment(i - 1) && !own(i - 1)) step = -1;
        else if (along > e.squaredNorm() && is_segment(i + 1) && !own(i + 2)) step = 1;
        if (step == 0 || step == -last_step) break;
        i += std::size_t(step);
        last_step = step;
    }
    *nearest = nearest_on_segment(p, i);
    *distance2 = (p - nearest->point).squaredNorm();
    if (last_step != 0) {
        // The segment we came from, when p sits over the joint.
        const std::size_t j = i - std::size_t(last_step);
        const SegmentPoint other = nearest_on_segment(p, j);
        const double d2 = (p - other.point).squaredNorm();
        if (d2 < *distance2) *distance2 = d2, *nearest = other, i = j;
    }
    return i;
}

std::size_t FoldContacts::near(const Vec3& point, uint32_t tube, double s, Anchor* out, std::size_t max) const {
    if (coarse_.empty() || tube + 1 >= tube_first_coarse_.size()) return 0;
    // The coarse sample of this tube nearest to s.
    const auto begin = coarse_.begin() + tube_first_coarse_[tube], end = coarse_.begin() + tube_first_coarse_[tube + 1];
    auto it = std::lower_bound(begin, end, s, [&](uint32_t i, double value) { return arc_[i] < value; });
    if (it == end || (it != begin && s - arc_[*(it - 1)] < arc_[*it] - s)) --it;
    const std::size_t k = std::size_t(it - coarse_.begin());
    const double threshold = 1.0 + kMaxBulgeReach;
    std::size_t count = 0;
    for (std::size_t f = folds_begin_[k]; f < folds_begin_[k + 1] && count < max; ++f) {
        std::size_t start = folds_[f];
        if (!is_segment(start)) --start;  // the last sample of a tube: its last segment
        SegmentPoint nearest;
        double distance2 = 0.0;
        const std::size_t segment = nearest_segment(point, tube, s, start, &nearest, &distance2);
        const double level = std::sqrt(distance2) / radius_[segment] + window_penalty(tube, s, tube_[segment], nearest.arc);
        // A ray point within query_radius of `point` is at least this much nearer.
        if (!(level - query_radius_ / radius_[segment] < threshold)) continue;
        bool known = false;
        for (std::size_t a = 0; a < count && !known; ++a)
            known = tube_[out[a].segment] == tube_[segment] &&
                    (out[a].segment > segment ? out[a].segment - segment : segment - out[a].segment) <= 2;
        if (!known) out[count++] = Anchor{uint32_t(segment), level};
    }
    return count;
}

double FoldContacts::level(const Vec3& p, uint32_t tube, double s, const Anchor& anchor, Vec3* gradient) const {
    SegmentPoint nearest;
    double distance2 = 0.0;
    const std::size_t i = nearest_segment(p, tube, s, anchor.segment, &nearest, &distance2);
    const double distance = std::sqrt(distance2), inverse_radius = 1.0 / radius_[i];
    *gradient = (distance > 0.0 ? inverse_radius / distance : 0.0) * (p - nearest.point);
    return distance * inverse_radius + window_penalty(tube, s, tube_[i], nearest.arc);
}

}  // namespace enteron::skinning
