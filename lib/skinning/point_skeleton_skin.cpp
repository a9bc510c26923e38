// SPDX-License-Identifier: Apache-2.0
#include "skinning/point_skeleton_skin.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "skinning/frame_buffers.h"

namespace enteron::skinning {

namespace {

// Newton projection stops after a step shorter than this, in R (see project_vertices).
constexpr double kLastStep = 0.02;

// Four floats in one SIMD register (GCC and Clang vector extensions; plain code elsewhere).
using float4 = float __attribute__((vector_size(16)));
using int4 = int32_t __attribute__((vector_size(16)));

float4 load4(const float* p) {
    float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
int4 reinterpret_cast_int4(float4 v) {
    int4 r;
    std::memcpy(&r, &v, sizeof r);
    return r;
}
float4 reinterpret_cast_float4(int4 v) {
    float4 r;
    std::memcpy(&r, &v, sizeof r);
    return r;
}
// floor and ceil to int without a library call (values are lattice indices, far from
// the int32 limits).
int32_t floor_int(double x) {
    const auto i = int32_t(x);
    return i - int32_t(x < double(i));
}
int32_t ceil_int(double x) {
    const auto i = int32_t(x);
    return i + int32_t(x > double(i));
}

float lane_sum(float4 v) { return (v[0] + v[1]) + (v[2] + v[3]); }

}  // namespace

PointSkeletonSkin::PointSkeletonSkin(const SkinSettings& settings) : Skin(settings) {
    const double R = settings_.radius, D = settings_.window, h = settings_.skeleton_spacing;
    support2_ = R * R + D * D;
    window_points_ = static_cast<std::size_t>(std::ceil(D / h));
    const std::size_t count = 2 * window_points_ + 1;
    window_lanes_ = (count + kLanes - 1) / kLanes * kLanes;
    window_mask_.assign(window_lanes_, 0.0f);
    std::fill_n(window_mask_.begin(), count, 1.0f);
    padding_ = std::max<std::size_t>(window_points_, 4);
    // Calibration on a skeleton along an arc of curvature k, at distance R in direction c
    // (bend_calibration.h), averaged over the two extreme phases of the points (a surface
    // point level with a skeleton point, and half-way between two).
    auto field_off_arc = [&](double r, double k, double c) {
        const Vec3 p = BendCalibration::point_off_arc(r, c);
        double sum = 0.0;
        for (double phase : {0.0, 0.5}) {
            double f = 0.0;
            const auto w = long(window_points_) + 1;
            for (long j = -w; j <= w; ++j) {
                const double d2 = (p - BendCalibration::arc_point(k, (double(j) + phase) * h)).squaredNorm();
                if (d2 < support2_) {
                    const double q = 1.0 - d2 / support2_;
                    f += h * q * q * q;
                }
            }
            sum += f;
        }
        return 0.5 * sum;
    };
    const auto window_field = [&](double k, double c) { return field_off_arc(R, k, c); };
    iso_ = window_field(0.0, 0.0);
    bend_.build(R, window_field);
    // Where no bulge can lift the field to the iso-value: a bulge raises the surface by at
    // most 4 kMaxBulgeReach / 27 of R (contact_profile.h); a fifth more than the straight
    // field there, less a quarter for the bend's scale.
    bulge_floor_ = 0.75 * field_off_arc((1.0 + 1.2 * 4.0 * kMaxBulgeReach / 27.0) * R, 0.0, 0.0);
}

void PointSkeletonSkin::load_skeleton() {
    // Single precision, structure of arrays, padded on both sides with points too far away
    // to contribute: the window sums and the nearest-point search run whole lane groups
    // without bounds checks. `excluded_` is 0 at the real points and huge elsewhere
    // (phantoms, padding), so that only real points are found nearest.
    const std::size_t n = skeleton_.size();
    const float far = 1e6f;
    const std::size_t padded = n + 2 * padding_ + 2 * kLanes;
    assign_buffer(x_, padded, far);
    assign_buffer(y_, padded, far);
    assign_buffer(z_, padded, far);
    assign_buffer(excluded_, padded, 1e30f);
    for (std::size_t j = 0; j < n; ++j) {
        const Vec3& p = skeleton_.position(j);
        x_[padding_ + j] = float(p.x());
        y_[padding_ + j] = float(p.y());
        z_[padding_ + j] = float(p.z());
    }
    std::fill_n(excluded_.begin() + std::ptrdiff_t(padding_ + skeleton_.phantoms()), skeleton_.intervals() + 1, 0.0f);
    // The bend at each point: the row of its curvature in the scale table, and the unit
    // vector towards the centre of curvature over R, so that -bend_axis.(q - x_j) is the c
    // of bend_calibration.h (times |q - x_j| / R).
    resize_buffer(bend_rows_, n);
    resize_buffer(bend_axes_, n);
    const double R = settings_.radius;
    for (std::size_t j = 0; j < n; ++j) {
        // The mean bend over the window: gradual as the points slide along the axis (the
        // spline's curvature at a point jumps at its control points).
        const Vec3 bend = skeleton_.mean_bend(skeleton_.arc_length(j), settings_.window);
        const double curvature = bend.norm();
        bend_rows_[j] = bend_.row(curvature);
        bend_axes_[j] = curvature > 0.0 ? Vec3((1.0 / (curvature * R)) * bend) : Vec3::Zero();
    }
    radii_.clear();
    if (settings_.radius_along.varies()) {
        resize_buffer(radii_, n);
        for (std::size_t j = 0; j < n; ++j) radii_[j] = settings_.radius_along.at_parameter(skeleton_.parameter(j), R);
    }
    resize_buffer(inverse_chord2_, n);
    for (std::size_t j = 0; j + 1 < n; ++j) {
        const Vec3 d = skeleton_.position(j + 1) - skeleton_.position(j);
        inverse_chord2_[j] = 1.0 / std::max(d.squaredNorm(), 1e-300);
    }
}

[[gnu::always_inline]] inline std::size_t PointSkeletonSkin::nearest_from(Vec3 p, std::size_t k, double* distance2) const {
    const std::size_t first = skeleton_.phantoms(), last = first + skeleton_.intervals();
    k = std::clamp(k, first, last);
    const float4 px = float4{} + float(p.x()), py = float4{} + float(p.y()), pz = float4{} + float(p.z());
    // The nearest of the 8 points k - 3 .. k + 4 (two lane groups, no branches); if it is
    // at either end of them, search again around it (a start more than a few points off).
    for (;;) {
        const std::size_t base = padding_ + k - 3;
        float d[8];
        for (std::size_t group = 0; group < 2; ++group) {
            const std::size_t j = base + kLanes * group;
            const float4 dx = px - load4(&x_[j]), dy = py - load4(&y_[j]), dz = pz - load4(&z_[j]);
            const float4 d2 = dx * dx + dy * dy + dz * dz + load4(&excluded_[j]);
            std::memcpy(&d[kLanes * group], &d2, sizeof d2);
        }
        int best = 3;
        for (int lane = 0; lane < 8; ++lane) best = d[lane] < d[best] ? lane : best;
        const std::size_t found = k - 3 + std::size_t(best);
        if ((best != 0 && best != 7) || found == k) {
            *distance2 = double(d[best]);
            return found;
        }
        k = found;
    }
}

template <bool kGradient>
[[gnu::always_inline]] inline float PointSkeletonSkin::window_sum(float qx, float qy, float qz, std::size_t k, float* gradient) const {
    // Skeleton points k - W .. k + W, then lanes past them, masked out. Four lanes at a
    // time (SSE on any x86-64, NEON on ARM).
    const std::size_t start = padding_ + k - window_points_;
    const float* x = x_.data() + start;
    const float* y = y_.data() + start;
    const float* z = z_.data() + start;
    const float4 inverse = float4{} + float(1.0 / support2_);
    const float4 px = float4{} + qx, py = float4{} + qy, pz = float4{} + qz;
    float4 f{}, gx{}, gy{}, gz{};
    for (std::size_t j = 0; j < window_lanes_; j += kLanes) {
        const float4 dx = px - load4(x + j), dy = py - load4(y + j), dz = pz - load4(z + j);
        float4 s = 1.0f - (dx * dx + dy * dy + dz * dz) * inverse;
        // max(s, 0) inside the window, 0 past it.
        s = reinterpret_cast_float4(reinterpret_cast_int4(s) & (s > float4{})) * load4(&window_mask_[j]);
        const float4 s2 = s * s;
        f += s2 * s;
        if constexpr (kGradient) {
            gx += s2 * dx;
            gy += s2 * dy;
            gz += s2 * dz;
        }
    }
    const auto h = float(skeleton_.spacing());
    if constexpr (kGradient) {
        const float scale = -6.0f * h * float(1.0 / support2_);
        gradient[0] = scale * lane_sum(gx);
        gradient[1] = scale * lane_sum(gy);
        gradient[2] = scale * lane_sum(gz);
    }
    return h * lane_sum(f);
}

double PointSkeletonSkin::field(Vec3 given, std::size_t k, Vec3* gradient, bool with_bulge) const {
    const std::size_t first = skeleton_.phantoms(), last = first + skeleton_.intervals();
    // Near a contact, the field of the point pulled towards the skeleton point by the bulge
    // (the surface swells by the factor 1 + D).
    double bulge = 0.0, bulge_slope = 0.0;
    Vec3 level_gradient = Vec3::Zero();
    const Vec3& skeleton_point = skeleton_.position(k);
    if (with_bulge && !bulge_reach_.empty()) bulge = bulge_at(given, k, &bulge_slope, &level_gradient);
    const Vec3 p = bulge > 0.0 ? Vec3(skeleton_point + (1.0 / (1.0 + bulge)) * (given - skeleton_point)) : given;
    // Beyond an end: the field of the straight continuation, made radial about the end
    // point, so the surface closes as a hemisphere of radius R.
    Vec3 centre = Vec3::Zero(), q = p;
    bool radial = false;
    if (k == first || k == last) {
        const Vec3 end = skeleton_.position(k), t = skeleton_.tangent(k);
        const Vec3 d = p - end;
        const double along = d.dot(t);
        if ((k == first && along < 0.0) || (k == last && along > 0.0)) {
            const Vec3 side = d - along * t;
            // On (or within round-off of) the axis line: any perpendicular will do.
            const Vec3 direction = side.norm() > 1e-9 * d.norm() ? normalized_or(side, side) : any_perpendicular(t);
            q = end + d.norm() * direction;
            centre = end;
            radial = true;
        }
    }
    // With a radius profile, q stretched across the axis at k by R / r (about the end point
    // beyond an end, where the field is radial).
    const double stretch = radii_.empty() ? 1.0 : stretch_at(p, k);
    if (!radii_.empty()) {
        const Vec3& x = skeleton_.position(k);
        const Vec3 d = q - x;
        const Vec3& t = skeleton_.tangent(k);
        const double along = radial ? 0.0 : d.dot(t);
        q = x + along * t + stretch * (d - along * t);
    }
    // The field scaled for the bend of the axis at k (bend_calibration.h), with c taken as
    // the cosine of q's direction off the axis from the outward direction times |q - x_k| / R.
    const BendCalibration::Row& bend_row = bend_rows_[k];
    const Vec3& bend_axis = bend_axes_[k];
    double d_scale_dc = 0.0;
    const double scale = BendCalibration::scale(bend_row, -bend_axis.dot(q - skeleton_.position(k)), &d_scale_dc);
    if (gradient == nullptr) return scale * window_sum<false>(float(q.x()), float(q.y()), float(q.z()), k, nullptr);
    float g[3];
    const double f = window_sum<true>(float(q.x()), float(q.y()), float(q.z()), k, g);
    // grad (scale F) = scale grad F + F d scale/dc grad c, with grad c = -bend_axis.
    const Vec3 grad = scale * Vec3{g[0], g[1], g[2]} - (f * d_scale_dc) * bend_axis;
    Vec3 at_p = grad;
    if (radial) {
        // F(p) = G(|p - end|): the gradient is radial with the slope of G.
        const Vec3 r = q - centre;
        const double rn = r.norm();
        const Vec3 dir = normalized_or(p - centre, Vec3{0, 0, 1});
        at_p = (rn > 0.0 ? grad.dot(r) / rn : 0.0) * dir;
        if (!radii_.empty()) at_p *= stretch;
    } else if (!radii_.empty()) {
        // Through the stretch (symmetric): R / r across the axis, 1 along it. (The radius'
        // own change along the axis, a few % of R per R at most, is left out: the Newton
        // steps converge all the same.)
        const Vec3& t = skeleton_.tangent(k);
        at_p = stretch * grad + ((1.0 - stretch) * grad.dot(t)) * t;
    }
    // Through the pull: p = c + (given - c) / (1 + D(x(given))).
    const double inverse = 1.0 / (1.0 + bulge);
    *gradient = bulge > 0.0 ? Vec3(inverse * at_p - (bulge_slope * inverse * inverse * at_p.dot(given - skeleton_point)) *
                                                        level_gradient)
                            : at_p;
    return scale * f;
}

void PointSkeletonSkin::prepare_contacts() {
    bulge_reach_.clear();
    if (!settings_.contact_surfaces) return;
    const double R = settings_.radius, h = skeleton_.spacing();
    folds_.build(skeleton_, R, 1.5 * R, settings_.radius_along);
    if (contact_cosine_.size() != kContactRays) {
        contact_cosine_.resize(kContactRays);
        contact_sine_.resize(kContactRays);
        for (std::size_t j = 0; j < kContactRays; ++j) {
            contact_cosine_[j] = std::cos(2.0 * kPi * double(j) / double(kContactRays));
            contact_sine_[j] = std::sin(2.0 * kPi * double(j) / double(kContactRays));
        }
    }
    // Rings every R / 2 along the real skeleton points, the last at the last point.
    contact_stride_ = std::max<std::size_t>(1, std::size_t(std::lround(0.5 * R / h)));
    const std::size_t first = skeleton_.phantoms(), intervals = skeleton_.intervals();
    const std::size_t rings = (intervals + contact_stride_ - 1) / contact_stride_ + 1;
    resize_buffer(bulge_reach_, rings);
    resize_buffer(contact_rays_, rings * kContactRays);
    double free[kContactRays], out[kContactRays];
    RingContacts::Ring ring;
    ring.rays = kContactRays;
    ring.cosine = contact_cosine_.data();
    ring.sine = contact_sine_.data();
    ring.measure_all = true;
    const double ceiling = 2.0 + kMaxBulgeReach;  // a level no bulge reaches
    for (std::size_t m = 0; m < rings; ++m) {
        const std::size_t k = first + std::min(m * contact_stride_, intervals);
        ring.centre = skeleton_.position(k);
        ring.normal = frames_.normal(k);
        ring.binormal = frames_.binormal(k);
        ring.tangent = skeleton_.tangent(k);
        ring.arc_length = skeleton_.arc_length(k);
        ring.curvature = skeleton_.mean_bend(ring.arc_length, settings_.window);
        ring.radius = radii_.empty() ? R : radii_[k];
        std::fill_n(free, kContactRays, ring.radius);
        bulge_reach_[m] = contacts_.deform(folds_, ring, free, out).bulge_reach;
        for (std::size_t j = 0; j < kContactRays; ++j) {
            ContactRaySample& sample = contact_rays_[m * kContactRays + j];
            sample.point = ring.centre + ring.radius * contacts_.direction(j);
            const double level = contacts_.level(j);
            sample.level = std::min(level, ceiling);
            sample.gradient = level < ceiling ? contacts_.gradient(j) : Vec3(Vec3::Zero());
        }
    }
}

double PointSkeletonSkin::bulge_at(const Vec3& p, std::size_t k, double* slope, Vec3* gradient) const {
    // The two contact rings around k, and their reach.
    const std::size_t first = skeleton_.phantoms(), rings = bulge_reach_.size();
    const double position = double(std::min(k - std::min(k, first), skeleton_.intervals())) / double(contact_stride_);
    const std::size_t m0 = std::min(std::size_t(position), rings - 2);
    const double along = std::clamp(position - double(m0), 0.0, 1.0);
    const double w = (1.0 - along) * bulge_reach_[m0] + along * bulge_reach_[m0 + 1];
    if (!(w > 0.0)) return 0.0;
    // The two rays around p's angle, in the frames along the skeleton (which do not twist).
    const double around = turns_around(p - skeleton_.position(k), frames_.normal(k), frames_.binormal(k)) *
                          double(kContactRays);
    const std::size_t j0 = std::min(std::size_t(around), kContactRays - 1), j1 = j0 + 1 < kContactRays ? j0 + 1 : 0;
    const double turn = around - double(j0);
    double level = 0.0;
    Vec3 g = Vec3::Zero();
    for (std::size_t m : {m0, m0 + 1}) {
        const double wm = m == m0 ? 1.0 - along : along;
        for (std::size_t j : {j0, j1}) {
            const double weight = wm * (j == j0 ? 1.0 - turn : turn);
            const ContactRaySample& sample = contact_rays_[m * kContactRays + j];
            level += weight * (sample.level + sample.gradient.dot(p - sample.point));
            g += weight * sample.gradient;
        }
    }
    // x for a free radius of R: o - 1.
    const double x = level - 1.0;
    if (!(x > 0.0)) return 0.0;  // inside the other fold: the union's
    *gradient = g;
    return contact_deformation(x, w, slope);
}

double PointSkeletonSkin::stretch_at(const Vec3& p, std::size_t k) const {
    // The foot of p along the tangent at k, as a fraction of the way to the neighbour on
    // that side: r is linear between the two skeleton points.
    const double along = (p - skeleton_.position(k)).dot(skeleton_.tangent(k));
    const std::size_t neighbour = along >= 0.0 ? std::min(k + 1, skeleton_.size() - 1) : (k > 0 ? k - 1 : 0);
    const double inverse_chord2 = neighbour == k ? 0.0 : inverse_chord2_[std::min(k, neighbour)];
    const double w = std::min(1.0, std::fabs(along) * std::sqrt(inverse_chord2));
    return settings_.radius / ((1.0 - w) * radii_[k] + w * radii_[neighbour]);
}

double PointSkeletonSkin::band_field(const Vec3& p, std::size_t k) const {
    // The bulge only raises the field: a corner inside stays inside and one below the floor
    // stays outside, and marching cubes needs only their sides (the Newton steps of pass 4
    // then project every vertex onto the bulged surface).
    const double plain = field(p, k, nullptr, false);
    if (bulge_reach_.empty() || plain >= iso_ || plain <= bulge_floor_) return plain;
    return field(p, k, nullptr, true);
}

void PointSkeletonSkin::splat() {
    const double R = settings_.radius, v = settings_.voxel_size, inverse_v = 1.0 / v, h = skeleton_.spacing();
    const double reach = R + 2.0 * v;
    // Every `stride`-th skeleton point (about one per R) splats the piece of the band
    // around it: a disc-like cylinder on its tangent t, of half-thickness `half` and radius
    // `radius`, wide enough to hold every corner within `reach` of the skeleton points
    // nearer to it than to the next splatted point (at most H / 2 away in arc length).
    // For such a corner p, near skeleton point x_j with tangent t_j (p - x_j is within h of
    // being normal to t_j), |(p - c).t| <= H / 2 + h + reach |t_j - t| and its distance to
    // the cylinder's axis is at most reach + H / 2 |t_j - t|: straight, the discs tile the
    // band with little overlap; on a bend they thicken by the turn of the tangent. (Spheres
    // around the same points would visit about twice as many corners.)
    const std::size_t stride = std::max<std::size_t>(1, std::size_t(std::lround(R / h)));
    const double half_gap = 0.5 * double(stride) * h;
    const std::size_t first = skeleton_.phantoms(), last = first + skeleton_.intervals();
    grid_.reset(v, grid_.block_count() + 64);
    using G = SparseVoxelGrid;
    constexpr int kCache = 4;  // blocks per axis of the block index cache
    uint32_t blocks[kCache * kCache * kCache];
    for (std::size_t k = first; k <= last; k = k == last ? last + 1 : std::min(k + stride, last)) {
        const Vec3 c = skeleton_.position(k), t = skeleton_.tangent(k);
        double turn = 0.0;  // max |t_j - t| over the points this disc stands for
        for (std::size_t j = k - std::min(k - first, stride); j <= std::min(last, k + stride); ++j) {
            const Vec3 d = skeleton_.tangent(j) - t;
            turn = std::max(turn, d.squaredNorm());
        }
        turn = std::sqrt(turn);
        // The end points also stand for the hemispherical caps beyond them.
        const double half = half_gap + h + reach * turn + (k == first || k == last ? reach : 0.0);
        const double radius = reach + half_gap * turn, radius2 = radius * radius;
        // Lattice bounds: the disc's extent along each axis.
        const double tt[3] = {t.x(), t.y(), t.z()}, cc[3] = {c.x(), c.y(), c.z()};
        int32_t lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            const double extent = half * std::fabs(tt[a]) + radius * std::sqrt(std::max(0.0, 1.0 - tt[a] * tt[a]));
            lo[a] = ceil_int((cc[a] - extent) * inverse_v);
            hi[a] = floor_int((cc[a] + extent) * inverse_v);
        }
        const int32_t bx0 = G::block_of(lo[0]), by0 = G::block_of(lo[1]), bz0 = G::block_of(lo[2]);
        const bool cached = G::block_of(hi[0]) - bx0 < kCache && G::block_of(hi[1]) - by0 < kCache &&
                            G::block_of(hi[2]) - bz0 < kCache;
        if (cached) std::fill_n(blocks, kCache * kCache * kCache, G::kMissing);
        const double A = 1.0 - t.x() * t.x();  // the cylinder along a row: A X^2 + B X + C <= 0
        for (int32_t z = lo[2]; z <= hi[2]; ++z) {
            const double dz = z * v - c.z();
            const int32_t bz = G::block_of(z);
            for (int32_t y = lo[1]; y <= hi[1]; ++y) {
                const double dy = y * v - c.y();
                // Row (y, z): p - c = (X, dy, dz); (p - c).t = X t_x + e.
                const double e = dy * t.y() + dz * t.z();
                const double C = dy * dy + dz * dz - e * e - radius2, B = -2.0 * t.x() * e;
                double x_lo = -1e300, x_hi = 1e300;
                if (A > 1e-12) {
                    const double discriminant = B * B - 4.0 * A * C;
                    if (discriminant < 0.0) continue;
                    const double root = std::sqrt(discriminant);
                    x_lo = (-B - root) / (2.0 * A);
                    x_hi = (-B + root) / (2.0 * A);
                } else if (C > 0.0) {
                    continue;
                }
                if (std::fabs(t.x()) > 1e-12) {
                    const double a0 = (-half - e) / t.x(), a1 = (half - e) / t.x();
                    x_lo = std::max(x_lo, std::min(a0, a1));
                    x_hi = std::min(x_hi, std::max(a0, a1));
                } else if (std::fabs(e) > half) {
                    continue;
                }
                const int32_t x0 = std::max(lo[0], ceil_int((c.x() + x_lo) * inverse_v));
                const int32_t x1 = std::min(hi[0], floor_int((c.x() + x_hi) * inverse_v));
                const int32_t by = G::block_of(y);
                const double dyz2 = dz * dz + dy * dy;
                // The row, block by block.
                for (int32_t xs = x0; xs <= x1;) {
                    const int32_t bx = G::block_of(xs), xe = std::min(x1, bx * kBlockSize + kBlockSize - 1);
                    uint32_t index;
                    if (cached) {
                        uint32_t& slot = blocks[(bx - bx0) + kCache * ((by - by0) + kCache * (bz - bz0))];
                        if (slot == G::kMissing) slot = grid_.touch(bx, by, bz);
                        index = slot;
                    } else {
                        index = grid_.touch(bx, by, bz);
                    }
                    VoxelBlock& block = grid_.block(index);
                    const std::size_t row = G::local_index(0, y - by * kBlockSize, z - bz * kBlockSize);
                    for (int32_t x = xs; x <= xe; ++x) {
                        const double dx = x * v - c.x();
                        uint64_t& nearest = block.nearest[row + std::size_t(x - bx * kBlockSize)];
                        nearest = std::min(nearest, nearest_key(float(dyz2 + dx * dx), uint32_t(k)));
                    }
                    xs = xe + 1;
                }
            }
        }
    }
}

void PointSkeletonSkin::evaluate_band() {
    const double v = settings_.voxel_size, reach = settings_.radius + 2.0 * v, reach2 = reach * reach;
    std::size_t evaluations = 0;
    for (std::size_t b = 0; b < grid_.block_count(); ++b) {
        VoxelBlock& block = grid_.block(b);
        const int32_t gx = block.coordinates[0] * kBlockSize, gy = block.coordinates[1] * kBlockSize,
                      gz = block.coordinates[2] * kBlockSize;
        for (int z = 0; z < kBlockSize; ++z)
            for (int y = 0; y < kBlockSize; ++y)
                for (int x = 0; x < kBlockSize; ++x) {
                    const std::size_t i = SparseVoxelGrid::local_index(x, y, z);
                    const int32_t start = nearest_point(block.nearest[i]);
                    if (start < 0) {
                        block.field[i] = -1.0f;
                        continue;
                    }
                    const Vec3 p{(gx + x) * v, (gy + y) * v, (gz + z) * v};
                    double d2 = 0.0;
                    const std::size_t k = nearest_from(p, std::size_t(start), &d2);
                    if (d2 >= reach2) {  // covered by a splat disc only: not in the band
                        block.nearest[i] = kOutsideBand;
                        block.field[i] = -1.0f;
                        continue;
                    }
                    block.nearest[i] = nearest_key(float(d2), uint32_t(k));
                    block.field[i] = float(band_field(p, k));
                    ++evaluations;
                }
    }
    evaluations_ += evaluations;
}

void PointSkeletonSkin::project_vertices() {
    const double R = settings_.radius, v = settings_.voxel_size;
    const double length = skeleton_.length();
    const std::size_t first = skeleton_.phantoms(), last = first + skeleton_.intervals();
    const double last_step2 = kLastStep * R * kLastStep * R;
    std::size_t evaluations = 0;
    for (std::size_t i = 0; i < seeds_.size(); ++i) {
        Vec3 p{mesh_.positions[3 * i], mesh_.positions[3 * i + 1], mesh_.positions[3 * i + 2]};
        double d2 = 0.0;
        std::size_t k = nearest_from(p, std::size_t(seeds_[i]), &d2);
        // Newton steps along the gradient onto the iso-surface, each at most a voxel, until
        // a step is below R / 50. Newton converges quadratically: after a step l the vertex
        // is within about 2 l^2 / R of the iso-surface, below R / 1000 (on the settled 6 m
        // pile: at most 8e-4 R, against 0.7 % R RMS of radius error of the surface itself).
        // A lattice-edge vertex starts within about 1 % of R, so one evaluation is usually
        // enough; a vertex where two folds meet takes more. The normal is the gradient of
        // the last evaluation: along the gradient its direction hardly changes (by at most
        // 1e-3 rad on the pile). (Moving along the lattice edge instead keeps more vertices
        // where two folds meet short of the surface, by up to 6 % of R, and flips as many
        // triangles there.)
        Vec3 g = Vec3::Zero();
        for (int iteration = 0; iteration < 4; ++iteration) {
            const double f = field(p, k, &g);
            ++evaluations;
            const double g2 = g.squaredNorm();
            if (!(g2 > 0.0)) break;
            const double along = (f - iso_) / g2;  // the step is along * g
            const double step2 = along * along * g2;
            const double scale = step2 > v * v ? v / std::sqrt(step2) : 1.0;
            p = p - (scale * along) * g;
            k = nearest_from(p, k, &d2);
            if (step2 < last_step2) break;
        }

        const Vec3 n = normalized_or(-1.0 * g, Vec3{0, 0, 1});
        // u: project p on the axis polyline next to its nearest skeleton point, the foot
        // w of the way from point a to a + 1.
        std::size_t foot_a = k;
        double foot_w = 0.0;
        double best = 1e300;
        for (std::size_t a : {k - 1, k}) {
            if (a < first || a + 1 > last) continue;
            const Vec3 d = skeleton_.position(a + 1) - skeleton_.position(a);
            const double w = std::clamp((p - skeleton_.position(a)).dot(d) * inverse_chord2_[a], 0.0, 1.0);
            const Vec3 foot = skeleton_.position(a) + w * d;
            const double distance2 = (p - foot).squaredNorm();
            if (distance2 < best) {
                best = distance2;
                foot_a = a;
                foot_w = w;
            }
        }
        const double s = skeleton_.arc_length(foot_a) + foot_w * skeleton_.spacing();
        // The axis' frame at the foot, blended between its two skeleton points: the tangent
        // along u (made perpendicular to the normal) and v, the angle of p around the axis.
        const std::size_t b = std::min(foot_a + 1, skeleton_.size() - 1);
        const Vec3 foot = (1.0 - foot_w) * skeleton_.position(foot_a) + foot_w * skeleton_.position(b);
        const Vec3 axis_tangent = (1.0 - foot_w) * skeleton_.tangent(foot_a) + foot_w * skeleton_.tangent(b);
        const Vec3 frame_normal = (1.0 - foot_w) * frames_.normal(foot_a) + foot_w * frames_.normal(b);
        const Vec3 frame_binormal = (1.0 - foot_w) * frames_.binormal(foot_a) + foot_w * frames_.binormal(b);
        store_vec3(mesh_.positions, i, p);
        store_vec3(mesh_.normals, i, n);
        store_vec3(mesh_.tangents, i, normalized_or(axis_tangent - axis_tangent.dot(n) * n, axis_tangent));
        mesh_.u[i] = float(length > 0.0 ? std::clamp(s / length, 0.0, 1.0) : 0.0);
        mesh_.v[i] = float(turns_around(p - foot, frame_normal, frame_binormal));
    }
    evaluations_ += evaluations;
}

void PointSkeletonSkin::rebuild() {
    const double D = settings_.window, h = settings_.skeleton_spacing;
    evaluations_ = 0;
    skeleton_.build(table_, points_.data(), axis_count(), AxisSamples::intervals_for(table_.total_length(), h),
                    D + 2.0 * h, AxisSamples::Curvature::compute);
    frames_.build(&skeleton_.position(0), &skeleton_.tangent(0), skeleton_.size());
    load_skeleton();
    prepare_contacts();
    splat();
    evaluate_band();
    cubes_.extract(grid_, iso_, mesh_, seeds_);
    topology_changed_ = true;  // new triangles every time
    project_vertices();
}

}  // namespace enteron::skinning
