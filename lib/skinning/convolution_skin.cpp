// SPDX-License-Identifier: Apache-2.0
#include "skinning/convolution_skin.h"

#include <algorithm>
#include <cmath>

#include "skinning/frame_buffers.h"
#include "skinning/segment_kernel.h"

namespace enteron::skinning {

namespace {

// Skeleton points follow the curvature down to this fraction of skeleton_spacing.
constexpr double kFinestSkeleton = 1.0 / 8.0;

}  // namespace

double ConvolutionSkin::skeleton_spacing_for(double curvature) const {
    const double h = settings_.skeleton_spacing;
    if (!(settings_.skeleton_chord_error > 0.0)) return h;
    return RingPlacement::spacing_for(curvature, 0.0, settings_.skeleton_chord_error, kFinestSkeleton * h, h);
}

ConvolutionSkin::ConvolutionSkin(const SkinSettings& settings) : Skin(settings) {
    // Calibration: the windowed field of a skeleton (chords of the skeleton spacing along an
    // arc of curvature k, clipped to [-D, D]; with a curvature-following skeleton, the
    // spacing it takes on that arc) at distance R from it, in direction c.
    const double D = settings_.window, R = settings_.radius;
    auto window_field = [&](double k, double c) {
        const double h = skeleton_spacing_for(k);
        const auto pieces = static_cast<std::size_t>(std::ceil(2.0 * D / h));
        const Vec3 p = BendCalibration::point_off_arc(R, c);
        double sum = 0.0;
        for (std::size_t i = 0; i < pieces; ++i) {
            const double x0 = -D + double(i) * h, x1 = std::min(D, x0 + h);
            sum += segment_field(p, BendCalibration::arc_point(k, x0), BendCalibration::arc_point(k, x1));
        }
        return sum;
    };
    iso_ = window_field(0.0, 0.0);
    bend_.build(R, window_field);
}

void ConvolutionSkin::gather_window(double s) {
    // The skeleton segments over [s - D, s + D], those at the ends clipped there.
    const double D = settings_.window;
    const std::size_t last = skeleton_.size() - 1;
    std::size_t first_index = 0;
    if (skeleton_intervals_ == 0) {  // even: by arithmetic
        const double h = skeleton_.spacing(), e = double(skeleton_.phantoms());
        first_index = std::size_t(std::clamp(std::floor((s - D) / h + e), 0.0, double(last)));
    } else {
        std::size_t lo = 0, hi = last;  // the last sample at or before s - D
        while (hi - lo > 1) {
            const std::size_t mid = (lo + hi) / 2;
            (skeleton_.arc_length(mid) <= s - D ? lo : hi) = mid;
        }
        first_index = lo;
    }
    window_.clear();
    for (std::size_t i = first_index; i < last; ++i) {
        const double s0 = skeleton_.arc_length(i), s1 = skeleton_.arc_length(i + 1);
        if (s0 >= s + D) break;
        const Vec3 a = skeleton_.position(i), d = skeleton_.position(i + 1) - a;
        const double span = s1 - s0;
        const double lo = std::max(0.0, (s - D - s0) / span), hi = std::min(1.0, (s + D - s0) / span);
        if (!(hi > lo)) continue;
        window_.push_back(a + lo * d);
        window_.push_back(a + hi * d);
    }
}

double ConvolutionSkin::ring_radius(std::size_t k) const {
    return settings_.radius_along.at_parameter(rings_.parameter(k), settings_.radius);
}

double ConvolutionSkin::field(Vec3 p) const {
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < window_.size(); i += 2) sum += segment_field(p, window_[i], window_[i + 1]);
    return sum;
}

double ConvolutionSkin::solve_ray(Vec3 origin, Vec3 direction, double start, double iso) {
    const double R = settings_.radius, D = settings_.window;
    const double t_max = 3.0 * R;
    double lo = 0.0, hi = t_max;
    double t = std::clamp(start, 0.05 * R, t_max);
    for (int iteration = 0; iteration < 40; ++iteration) {
        const double value = field(origin + t * direction);
        ++evaluations_;
        const double f = value - iso;
        if (f > 0.0) lo = t; else hi = t;
        // Slope of the field of a straight window along the ray: exact for a straight axis,
        // a good model elsewhere; the bracket [lo, hi] catches the rest.
        const double slope = value * (-2.0 / t - t / (t * t + D * D));
        // Converged: the Newton step is negligible; t itself is returned, so that the same
        // axis again (warm start on this solution) gives the same mesh to the last bit.
        // (Tested before the bracket: on a solution, f = 0 puts t itself at the end of the
        // bracket, and bisecting away from it cost a warm-started vertex several evaluations
        // instead of one.)
        if (slope < 0.0 && std::fabs(f / slope) < 1e-7 * R) return t;
        double next = slope < 0.0 ? t - f / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        t = next;
    }
    return t;
}

void ConvolutionSkin::rebuild() {
    const double R = settings_.radius;
    const std::size_t S = settings_.segments;
    evaluations_ = 0;
    const double length = table_.total_length();
    const auto skeleton_curvature = settings_.contact_surfaces ? AxisSamples::Curvature::compute : AxisSamples::Curvature::skip;
    skeleton_intervals_ = 0;
    if (settings_.skeleton_chord_error > 0.0) {
        // The skeleton follows the curvature (ring_placement.h with a radius of 0): chords
        // within skeleton_chord_error of the axis, from skeleton_spacing down to an eighth.
        const double h = settings_.skeleton_spacing;
        bends_.build(table_, points_.data(), axis_count(), AxisSamples::intervals_for(length, 0.5 * std::min(R, h)), 0.0,
                     AxisSamples::Curvature::skip);
        const std::vector<double>& arcs =
            skeleton_placement_.place(bends_, 0.0, h, kFinestSkeleton * h, settings_.skeleton_chord_error, 0);
        skeleton_.build_at(table_, points_.data(), axis_count(), arcs, skeleton_curvature, settings_.window + h);
        skeleton_intervals_ = arcs.size() - 1;
    } else {
        skeleton_.build(table_, points_.data(), axis_count(), AxisSamples::intervals_for(length, settings_.skeleton_spacing),
                        settings_.window + settings_.skeleton_spacing, skeleton_curvature);
    }
    const std::size_t even_intervals = ring_intervals(length);
    if (settings_.ring_chord_error > 0.0) {
        // Levels of detail: rings closer where the axis bends (ring_placement.h), their
        // count in steps of a sixteenth of the even count when the topology is to stay.
        const double min_spacing = std::max(0.05 * R, settings_.ring_spacing / 16.0);
        const std::size_t level_step = settings_.stable_topology ? (even_intervals + 15) / 16 : 0;
        // (From the skeleton when it is even; else from the bends' even samples.)
        rings_.build_at(table_, points_.data(), axis_count(),
                        placement_.place(skeleton_intervals_ == 0 ? skeleton_ : bends_, R, settings_.ring_spacing,
                                         min_spacing, settings_.ring_chord_error, level_step),
                        AxisSamples::Curvature::skip);
    } else {
        rings_.build(table_, points_.data(), axis_count(), even_intervals, 0.0, AxisSamples::Curvature::skip);
    }
    const std::size_t n = rings_.size();
    frames_.build(&rings_.position(0), &rings_.tangent(0), n);
    if (grid_.segments() != S) previous_u_.clear();  // new vertex directions: no previous solution
    if (grid_.layout(n, S, settings_.cap_rings, mesh_.indices)) {
        topology_changed_ = true;
        mesh_.resize_vertices(grid_.vertex_count());
        grid_.around(mesh_.v.data());
    }

    // Starting radii: last frame's, at the same place along the axis (interpolated in u
    // when the rings moved or their number changed).
    // radius_ and previous_ (u_ and previous_u_) trade places every frame: keep their
    // capacities equal, or a size reached once would allocate again a frame later.
    resize_buffer(radius_, n * S);
    previous_.reserve(radius_.capacity());
    resize_buffer(u_, n);
    previous_u_.reserve(u_.capacity());
    for (std::size_t k = 0; k < n; ++k) u_[k] = rings_.fraction(k);
    if (previous_u_ == u_) {
        std::copy(previous_.begin(), previous_.begin() + std::ptrdiff_t(n * S), radius_.begin());
    } else if (previous_u_.size() >= 2) {
        std::size_t k0 = 0;
        for (std::size_t k = 0; k < n; ++k) {
            while (k0 + 2 < previous_u_.size() && previous_u_[k0 + 1] < u_[k]) ++k0;
            const double span = previous_u_[k0 + 1] - previous_u_[k0];
            const double w = std::clamp(span > 0.0 ? (u_[k] - previous_u_[k0]) / span : 0.0, 0.0, 1.0);
            for (std::size_t j = 0; j < S; ++j)
                radius_[k * S + j] = (1 - w) * previous_[k0 * S + j] + w * previous_[(k0 + 1) * S + j];
        }
    } else {
        for (std::size_t k = 0; k < n; ++k) std::fill_n(radius_.begin() + std::ptrdiff_t(k * S), S, ring_radius(k));
    }

    // The other folds, on the skeleton's polyline, for rays reaching up to 1.5 R.
    if (settings_.contact_surfaces) folds_.build(skeleton_, R, 1.5 * R, settings_.radius_along);
    resize_buffer(deformed_, n * S);
    touching_rings_ = 0;
    RingContacts::Ring ring;
    ring.tube = 0;
    ring.rays = S;
    ring.cosine = grid_.cosines();
    ring.sine = grid_.sines();
    // The free rays of every ring.
    for (std::size_t k = 0; k < n; ++k) {
        const double s = rings_.arc_length(k);
        gather_window(s);
        const Vec3 centre = rings_.position(k);
        const Vec3 nrm = frames_.normal(k), bin = frames_.binormal(k);
        // The bend of the axis here, for the iso-value of each ray (bend_calibration.h): its
        // mean over the window, which changes gradually as rings slide along the axis (the
        // spline's curvature at a point jumps at its control points).
        const Vec3 bend = skeleton_.mean_bend(s, settings_.window);
        const double curvature = bend.norm();
        const BendCalibration::Row bend_row = bend_.row(curvature);
        const double inverse_curvature = curvature > 0.0 ? 1.0 / curvature : 0.0;
        // With a radius profile each ray is solved in space stretched across the axis by
        // R / r (r the ring's radius): the field reaches the iso-value of radius R where the
        // ray is r long, exactly on a straight axis.
        const double stretch = R / ring_radius(k);
        const double bend_n = inverse_curvature * bend.dot(nrm), bend_b = inverse_curvature * bend.dot(bin);
        for (std::size_t j = 0; j < S; ++j) {
            const Vec3 direction = grid_.cosine(j) * nrm + grid_.sine(j) * bin;
            // c: cosine of the angle between the ray and the direction away from the centre of
            // curvature.
            const double c = -(grid_.cosine(j) * bend_n + grid_.sine(j) * bend_b);
            double unused = 0.0;
            const double iso = iso_ / BendCalibration::scale(bend_row, c, &unused);
            radius_[k * S + j] = solve_ray(centre, direction, stretch * radius_[k * S + j], iso) / stretch;
        }
    }
    // Contacts and the neighbouring rings.
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3 centre = rings_.position(k);
        const Vec3 nrm = frames_.normal(k), bin = frames_.binormal(k);
        ring.centre = centre;
        ring.normal = nrm;
        ring.binormal = bin;
        ring.tangent = rings_.tangent(k);
        ring.arc_length = rings_.arc_length(k);
        ring.radius = ring_radius(k);
        ring.curvature = skeleton_.mean_bend(ring.arc_length, settings_.window);
        ring.previous_centre = k > 0 ? &rings_.position(k - 1) : nullptr;
        ring.next_centre = k + 1 < n ? &rings_.position(k + 1) : nullptr;
        if (contacts_.deform(folds_, ring, &radius_[k * S], &deformed_[k * S]).touched) ++touching_rings_;
        const auto u = float(u_[k]);
        const std::size_t row = grid_.body_row(k);
        for (std::size_t j = 0; j < S; ++j) {
            const Vec3 direction = grid_.cosine(j) * nrm + grid_.sine(j) * bin;
            const std::size_t v = grid_.vertex(row, j);
            store_vec3(mesh_.positions, v, centre + deformed_[k * S + j] * direction);
            mesh_.u[v] = u;
        }
    }

    // Caps: hemispheres scaled, angle by angle, to the end ring's radius, cut to contacts.
    resize_buffer(cap_free_, S);
    resize_buffer(cap_deformed_, S);
    for (std::size_t row = 0; row < grid_.rows(); ++row) {
        const bool first = row <= grid_.cap_rings();
        if (!first && row < grid_.body_row(n - 1) + 1) continue;
        const std::size_t k = first ? 0 : n - 1;
        const Vec3 centre = rings_.position(k), t = rings_.tangent(k);
        const Vec3 nrm = frames_.normal(k), bin = frames_.binormal(k);
        const float u = first ? 0.0f : 1.0f;
        if (row == 0 || row + 1 == grid_.rows()) {
            double mean = 0.0;
            for (std::size_t j = 0; j < S; ++j) mean += deformed_[k * S + j];
            mean /= double(S);
            const std::size_t v = grid_.vertex(row, 0);
            store_vec3(mesh_.positions, v, centre + (first ? -mean : mean) * t);
            mesh_.u[v] = u;
            continue;
        }
        const double phi = grid_.cap_angle(row);
        ring.centre = centre;
        ring.normal = nrm;
        ring.binormal = bin;
        ring.tangent = t;
        ring.arc_length = rings_.arc_length(k);
        ring.radius = ring_radius(k);
        ring.tilt = phi;
        ring.keep_area = false;
        ring.previous_centre = ring.next_centre = nullptr;
        std::copy_n(&deformed_[k * S], S, cap_free_.begin());
        contacts_.deform(folds_, ring, cap_free_.data(), cap_deformed_.data());
        ring.tilt = 0.0;
        ring.keep_area = true;
        for (std::size_t j = 0; j < S; ++j) {
            const Vec3 direction = std::cos(phi) * (grid_.cosine(j) * nrm + grid_.sine(j) * bin) + std::sin(phi) * t;
            const std::size_t v = grid_.vertex(row, j);
            store_vec3(mesh_.positions, v, centre + cap_deformed_[j] * direction);
            mesh_.u[v] = u;
        }
    }
    grid_.grid_normals(mesh_.positions.data(), rings_.tangent(0), rings_.tangent(n - 1), mesh_.normals.data(),
                       mesh_.tangents.data());

    previous_.swap(radius_);
    previous_u_.swap(u_);
}

}  // namespace enteron::skinning
