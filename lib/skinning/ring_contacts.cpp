// SPDX-License-Identifier: Apache-2.0
#include "skinning/ring_contacts.h"

#include <algorithm>
#include <cmath>

#include "skinning/fold_over_limit.h"
#include "skinning/frame_buffers.h"

namespace enteron::skinning {

ContactRay RingContacts::measure(const FoldContacts& folds, const Ring& ring, const Vec3& p, const Vec3& d,
                                 double t0, double u) const {
    // The nearest fold in its own radii, and the slope of that level along the ray.
    double level = 1e30;
    Vec3 gradient = Vec3::Zero();
    for (std::size_t a = 0; a < folds_; ++a) {
        Vec3 g;
        const double o = folds.level(p, ring.tube, ring.arc_length, anchors_[a], &g);
        if (o < level) level = o, gradient = g;
    }
    // x = (R_A / t0) o - 1 at this u; dx/du = R_A d . grad o. As seen from u = 0 on the line.
    const double x = ring.radius / t0 * level - 1.0;
    const double slope = ring.radius * d.dot(gradient);
    return ContactRay{x - slope * u, slope};
}

bool RingContacts::measure_levels(const FoldContacts& folds, const Ring& ring, const double* free, double t_max,
                                  double below) {
    // Each fold's level on the rays it may bring below `below`: from a ray where the fold is
    // at level o, the next m rays (their points at most m delta apart, delta = 2 t_max
    // sin(pi / n)) are at least at o - m delta / R_F, so they are skipped while that stays
    // above `below`.
    const std::size_t n = ring.rays;
    const double spacing = 2.0 * t_max * std::sin(kPi / double(n));
    assign_buffer(level_, n, 1e30);
    assign_buffer(gradient_, n, Vec3(Vec3::Zero()));
    bool any = false;
    for (std::size_t a = 0; a < folds_; ++a) {
        const double radius = folds.radius(anchors_[a]), delta = spacing / radius;
        // No ray point is farther than t_max from the centre, where this fold is at its level.
        if (anchors_[a].level - t_max / radius >= below) continue;
        for (std::size_t j = 0; j < n;) {
            Vec3 g;
            const double o = folds.level(ring.centre + free[j] * direction_[j], ring.tube, ring.arc_length, anchors_[a], &g);
            if (o < level_[j]) level_[j] = o, gradient_[j] = g;
            any = any || o * ring.radius < free[j];
            j += 1 + (o > below ? std::size_t((o - below) / delta) : 0);
        }
    }
    return any;
}

double RingContacts::section(const double* t) const {
    const std::size_t n = direction_.size();
    double area = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t k = j + 1 < n ? j + 1 : 0;
        // Fan triangle (c, v_j, v_k): area wedge t_j t_k, centroid (t_j d_j + t_k d_k) / 3.
        area += wedge_[j] * t[j] * t[k] * (1.0 - (bend_[j] * t[j] + bend_[k] * t[k]) / 3.0);
    }
    return area;
}

double RingContacts::bulged(std::size_t j, double w) const {
    if (rays_[j].touches()) return cut_[j];
    return below_fold_over_limit(free_[j] * (1.0 + rays_[j].bulge_u(w)), limit_[j]);
}

double RingContacts::limited(std::size_t j, double t) const { return below_fold_over_limit(t, limit_[j]); }

RingContacts::Result RingContacts::deform(const FoldContacts& folds, const Ring& ring, const double* free,
                                          double* out) {
    Result result;
    const std::size_t n = ring.rays;
    resize_buffer(direction_, n);
    resize_buffer(limit_, n);
    resize_buffer(free_, n);
    const double across = std::cos(ring.tilt), along = std::sin(ring.tilt);
    for (std::size_t j = 0; j < n; ++j) {
        direction_[j] = across * (ring.cosine[j] * ring.normal + ring.sine[j] * ring.binormal) + along * ring.tangent;
        double limit = std::numeric_limits<double>::infinity();
        for (const Vec3* neighbour : {ring.previous_centre, ring.next_centre})
            if (neighbour != nullptr) limit = std::min(limit, fold_over_limit(ring.centre, direction_[j], *neighbour));
        limit_[j] = limit;
        free_[j] = free[j];
    }
    // 1. The other folds near the ring, and their level on each ray at its free radius.
    measured_ = false;
    folds_ = folds.empty() ? 0 : folds.near(ring.centre, ring.tube, ring.arc_length, anchors_, kMaxFolds);
    if (folds_ == 0) {
        for (std::size_t j = 0; j < n; ++j) out[j] = limited(j, free[j]);
        return result;
    }
    // First only where a fold may touch the ring (level below t0 / R_A): most rings near a
    // fold do not touch it and need nothing more. Where one does, every ray the bulge may
    // reach (level below (1 + kMaxBulgeReach) t0 / R_A).
    double t_max = 0.0;
    for (std::size_t j = 0; j < n; ++j) t_max = std::max(t_max, free[j]);
    const double touching = t_max / ring.radius, farthest = (1.0 + kMaxBulgeReach) * touching;
    if (!measure_levels(folds, ring, free, t_max, touching) && !ring.measure_all) {
        for (std::size_t j = 0; j < n; ++j) out[j] = limited(j, free[j]);
        return result;
    }
    measure_levels(folds, ring, free, t_max, farthest);
    measured_ = true;
    resize_buffer(rays_, n);
    resize_buffer(cut_, n);
    for (std::size_t j = 0; j < n; ++j) {
        const Vec3& d = direction_[j];
        rays_[j] = ContactRay{};
        if (level_[j] < 1e30) rays_[j] = ContactRay{ring.radius / free[j] * level_[j] - 1.0, ring.radius * d.dot(gradient_[j])};
        cut_[j] = limited(j, free[j]);
        if (!rays_[j].touches()) continue;
        // 2. Cut to the contact surface, then once more from the level measured there.
        result.touched = true;
        double u = rays_[j].contact_u();
        const ContactRay again = measure(folds, ring, ring.centre + free[j] * (1.0 + u) * d, d, free[j], u);
        u = again.touches() ? again.contact_u() : u;
        cut_[j] = limited(j, std::max(free[j] * (1.0 + u), 0.05 * ring.radius));
    }
    if (result.touched && ring.keep_area) {
        // 3. The bulge that gives the cross-section back its area.
        resize_buffer(wedge_, n);
        resize_buffer(bend_, n);
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t k = j + 1 < n ? j + 1 : 0;
            wedge_[j] = 0.5 * direction_[j].cross(direction_[k]).norm();
            bend_[j] = ring.curvature.dot(direction_[j]);
        }
        resize_buffer(trial_, n);
        for (std::size_t j = 0; j < n; ++j) trial_[j] = limited(j, free[j]);
        const double wanted = section(trial_.data()), cut = section(cut_.data());
        result.lost_area = wanted - cut;
        if (result.lost_area > 0.0) {
            // The free rays the bulge may reach; the others keep their radius.
            reserve_with_headroom(bulging_, n);
            bulging_.clear();
            for (std::size_t j = 0; j < n; ++j)
                if (!rays_[j].touches() && rays_[j].x0 < kMaxBulgeReach) bulging_.push_back(uint32_t(j));
            std::copy(cut_.begin(), cut_.end(), trial_.begin());
            const auto excess = [&](double w) {
                for (uint32_t j : bulging_) trial_[j] = bulged(j, w);
                return section(trial_.data()) - wanted;
            };
            // The area grows with w: regula falsi (Illinois) on [0, kMaxBulgeReach].
            double lo = 0.0, hi = kMaxBulgeReach, f_lo = -result.lost_area, f_hi = excess(hi);
            double w = hi;
            if (f_hi > 0.0) {
                int side = 0;
                for (int iteration = 0; iteration < 40; ++iteration) {
                    w = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
                    const double f = excess(w);
                    // Within a thousandth of the lost area: the volume to a millionth or so.
                    if (std::fabs(f) <= 1e-3 * result.lost_area || hi - lo < 1e-9) break;
                    if (f < 0.0) {
                        lo = w, f_lo = f;
                        if (side == -1) f_hi *= 0.5;
                        side = -1;
                    } else {
                        hi = w, f_hi = f;
                        if (side == 1) f_lo *= 0.5;
                        side = 1;
                    }
                }
            }
            result.bulge_reach = w;
            if (!(f_hi > 0.0)) result.short_area = std::max(0.0, -excess(w));  // even the largest bulge falls short
            std::copy(trial_.begin(), trial_.end(), cut_.begin());
        }
    }
    // 4. A bulged ray must not push into a fold (a third one, or its own past the model).
    for (std::size_t j = 0; j < n; ++j) {
        out[j] = cut_[j];
        if (rays_[j].touches() || !(cut_[j] > limited(j, free[j]))) continue;
        const double u = cut_[j] / free[j] - 1.0;
        const ContactRay there = measure(folds, ring, ring.centre + cut_[j] * direction_[j], direction_[j], free[j], u);
        const double x = there.x0 + there.G * u;
        if (x < u) out[j] = limited(j, free[j] * (1.0 + std::min(u, there.contact_u())));
    }
    return result;
}

}  // namespace enteron::skinning
