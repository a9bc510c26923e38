// SPDX-License-Identifier: Apache-2.0
#include "mechanics/clamped_ends.h"

#include <algorithm>
#include <cmath>

#include "base/error.h"

namespace enteron::mechanics {

namespace {

using Mat3 = Eigen::Matrix3d;

// Block (i, j) of the symmetric system between control points i and j (|i - j| <= 3).
Mat3 block(const SystemMatrix& system, std::size_t i, std::size_t j) {
    Mat3 m;
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) m(r, c) = system.at(3 * i + r, 3 * j + c);
    return m;
}

// Writes block (i, j) (and so, by symmetry, block (j, i)) into the lower band.
void set_block(SystemMatrix& system, std::size_t i, std::size_t j, const Mat3& m) {
    if (i < j) return set_block(system, j, i, m.transpose());
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c)
            if (i != j || c <= r) system.lower(3 * i + r, 3 * j + c) = m(r, c);
}

std::size_t distance(std::size_t a, std::size_t b) { return a > b ? a - b : b - a; }

// Control points more than this apart share no segment: their block is zero.
constexpr std::size_t kCoupledPoints = 3;

}  // namespace

Vec3 clamped_end_tangent(const double* points, std::size_t count, bool first_end) {
    if (first_end) return 0.5 * (4.0 * point_at(points, 1) - 3.0 * point_at(points, 0) - point_at(points, 2));
    return 0.5 * (3.0 * point_at(points, count - 1) - 4.0 * point_at(points, count - 2) + point_at(points, count - 3));
}

bool clamped_end_is_degenerate(const double* points, std::size_t count, bool first_end) {
    const std::size_t end = first_end ? 0 : count - 1, near = first_end ? 1 : count - 2, far = first_end ? 2 : count - 3;
    // Against the chords' own length: a tangent at round-off level of them has no direction.
    const double scale = (point_at(points, near) - point_at(points, end)).norm() +
                         (point_at(points, far) - point_at(points, near)).norm();
    return !(clamped_end_tangent(points, count, first_end).norm() > 1e-9 * scale);
}

ClampedEnds::ClampedEnds(bool first, bool last, const double* start_points, std::size_t count)
    : control_points_(count) {
    if (count < 4 || (first && last && count < 6))
        throw Error(ErrorCode::internal, "clamped ends need 4 control points, 6 with both ends");
    for (const bool first_end : {true, false}) {
        if (!(first_end ? first : last)) continue;
        if (clamped_end_is_degenerate(start_points, count, first_end))
            throw Error(ErrorCode::internal, "a clamped end's tangent is degenerate");
        Clamp& clamp = clamps_[count_++];
        clamp.end = first_end ? 0 : count - 1;
        clamp.near = first_end ? 1 : count - 2;
        clamp.far = first_end ? 2 : count - 3;
        clamp.direction = clamped_end_tangent(start_points, count, first_end).normalized();
        // e_1: across d, from the coordinate axis least aligned with it; e_2 = d x e_1.
        Vec3 axis = Vec3::Zero();
        int least = 0;
        clamp.direction.cwiseAbs().minCoeff(&least);
        axis[least] = 1.0;
        clamp.across[0] = (axis - axis.dot(clamp.direction) * clamp.direction).normalized();
        clamp.across[1] = clamp.direction.cross(clamp.across[0]);
    }
}

const ClampedEnds::Clamp* ClampedEnds::find(bool first_end) const {
    for (std::size_t k = 0; k < count_; ++k)
        if ((clamps_[k].end == 0) == first_end) return &clamps_[k];
    return nullptr;
}

Vec3 ClampedEnds::direction(bool first_end) const {
    const Clamp* clamp = find(first_end);
    return clamp != nullptr ? clamp->direction : Vec3::Zero();
}

void ClampedEnds::attach(bool first_end, const RigidFrames& frames, std::size_t frame, double t) {
    Clamp* clamp = find(first_end);
    if (clamp == nullptr) throw Error(ErrorCode::internal, "attaching an end that is not clamped");
    frames_ = &frames;
    clamp->frame = frame;
    clamp->rate[0] = clamp->rate[1] = 0.0;
    if (frame == kWorld) return;
    const FramePlacement placement = frames.at(frame, t);
    clamp->local_direction = placement.rotation.transpose() * clamp->direction;
    for (int e = 0; e < 2; ++e) clamp->local_across[e] = placement.rotation.transpose() * clamp->across[e];
}

bool ClampedEnds::prescribe(State& state, double dt, double speed_limit) {
    bool turned = false;
    for (std::size_t k = 0; k < count_; ++k) {
        Clamp& c = clamps_[k];
        if (c.frame == kWorld) continue;
        const Eigen::Matrix3d& rotation = frames_->at_end(c.frame).rotation;
        const Vec3 direction = rotation * c.local_direction;
        if (direction != c.direction) turned = true;
        c.direction = direction;
        for (int e = 0; e < 2; ++e) c.across[e] = rotation * c.local_across[e];
        // The rates that put u on d at the end of the step; the near point's velocity change
        // they ask (u's rate is 4 v_1 + ...) bounded by the speed limit.
        const Vec3 u = tangent_sum(c, state.q.data());
        double rate[2] = {-c.across[0].dot(u) / dt, -c.across[1].dot(u) / dt};
        const double change = 0.25 * std::hypot(rate[0], rate[1]);
        if (change > speed_limit)
            for (double& r : rate) r *= speed_limit / change;
        // v_1 += e_k (rate_k - e_k . u(v)) / 4: the velocity meets the constraint at the
        // start, so the explicit integrators (which hold its rate) keep it through the step.
        const Vec3 u_rate = tangent_sum(c, state.v.data());
        for (int e = 0; e < 2; ++e) {
            c.rate[e] = rate[e];
            point_at(state.v.data(), c.near) += c.across[e] * (0.25 * (rate[e] - c.across[e].dot(u_rate)));
        }
    }
    return turned;
}

void ClampedEnds::save_attachments(StateWriter& out) const {
    out.u32(static_cast<uint32_t>(count_));
    for (std::size_t k = 0; k < count_; ++k) {
        const Clamp& c = clamps_[k];
        out.u32(c.frame == kWorld ? 0u : static_cast<uint32_t>(c.frame) + 1u);
        out.f64s(c.direction.data(), 3);
        for (const Vec3& across : c.across) out.f64s(across.data(), 3);
        out.f64s(c.local_direction.data(), 3);
        for (const Vec3& across : c.local_across) out.f64s(across.data(), 3);
    }
}

void ClampedEnds::restore_attachments(StateReader& in, const RigidFrames& frames) {
    if (in.count("clamped ends", clamps_.size()) != count_) in.fail("the saved scene clamps other ends");
    std::array<Clamp, 2> clamps = clamps_;
    for (std::size_t k = 0; k < count_; ++k) {
        Clamp& c = clamps[k];
        const uint32_t frame = in.index("frame of a clamped end (0: the world)", frames.size() + 1);
        c.frame = frame == 0 ? kWorld : std::size_t{frame} - 1;
        in.f64s("clamped end's direction", 3, c.direction.data());
        for (Vec3& across : c.across) in.f64s("clamped end's cross direction", 3, across.data());
        in.f64s("clamped end's direction in its frame", 3, c.local_direction.data());
        for (Vec3& across : c.local_across) in.f64s("clamped end's cross direction in its frame", 3, across.data());
        // An orthonormal frame (d, e_1, e_2), in the world and in the obstacle's frame.
        Eigen::Matrix3d world, local;
        world << c.direction, c.across[0], c.across[1];
        local << c.local_direction, c.local_across[0], c.local_across[1];
        const double off = (world.transpose() * world - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
        const double local_off = (local.transpose() * local - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
        if (!(off < 1e-9) || (c.frame != kWorld && !(local_off < 1e-9)))
            in.fail("a clamped end's directions are not orthonormal");
        c.rate[0] = c.rate[1] = 0.0;
    }
    if (in.checking()) return;
    clamps_ = clamps;
    frames_ = &frames;
}

bool ClampedEnds::constrains(std::size_t control_point) const {
    for (std::size_t k = 0; k < count_; ++k)
        if (control_point == clamps_[k].near || control_point == clamps_[k].far) return true;
    return false;
}

void ClampedEnds::reduce(SystemMatrix& system) const {
    for (std::size_t k = 0; k < count_; ++k) {
        const Clamp& c = clamps_[k];
        Mat3 frame;  // R = [d e_1 e_2]
        frame << c.direction, c.across[0], c.across[1];
        const Mat3 a11 = block(system, c.near, c.near);
        const Mat3 a12 = block(system, c.near, c.far);
        const Mat3 a22 = block(system, c.far, c.far);
        // Every other point that shares a segment with q_1 or q_2:
        //   A'_1j = R^T A_1j / 4,   A'_2j = A_1j / 4 + A_2j.
        const std::size_t low = std::min(c.near, c.far), high = std::max(c.near, c.far);
        const std::size_t first = low >= kCoupledPoints ? low - kCoupledPoints : 0;
        const std::size_t last = std::min(control_points_ - 1, high + kCoupledPoints);
        for (std::size_t j = first; j <= last; ++j) {
            if (j == c.near || j == c.far) continue;
            const bool near_coupled = distance(j, c.near) <= kCoupledPoints;
            const Mat3 a1j = near_coupled ? block(system, c.near, j) : Mat3::Zero();
            if (near_coupled) set_block(system, c.near, j, frame.transpose() * a1j / 4.0);
            if (distance(j, c.far) <= kCoupledPoints) set_block(system, c.far, j, a1j / 4.0 + block(system, c.far, j));
        }
        //   A'_11 = R^T A_11 R / 16,   A'_12 = R^T (A_11 / 4 + A_12) / 4,
        //   A'_22 = A_11 / 16 + (A_12 + A_21) / 4 + A_22.
        set_block(system, c.near, c.near, frame.transpose() * a11 * frame / 16.0);
        set_block(system, c.near, c.far, frame.transpose() * (a11 / 4.0 + a12) / 4.0);
        set_block(system, c.far, c.far, a11 / 16.0 + (a12 + a12.transpose()) / 4.0 + a22);
        // The components of u across d are the constraint's: identity rows.
        system.make_identity_row(3 * c.near + 1);
        system.make_identity_row(3 * c.near + 2);
    }
}

void ClampedEnds::reduce_rhs(double* rhs, const double* velocity) const {
    for (std::size_t k = 0; k < count_; ++k) {
        const Clamp& c = clamps_[k];
        const Vec3 b1 = point_at(rhs, c.near);
        // b'_1 = R^T b_1 / 4 (its components on d, e_1, e_2), b'_2 = b_1 / 4 + b_2.
        Vec3 reduced(c.direction.dot(b1) / 4.0, 0.0, 0.0);
        for (int e = 0; e < 2; ++e) {
            // The rows across d: the change that puts u = 4 v_1 - v_2 (with v_0) back on d,
            // or on the rate that turns it with its frame (accelerations keep that rate).
            const double off = velocity == nullptr ? 0.0 : c.across[e].dot(tangent_sum(c, velocity));
            reduced[1 + e] = c.frame == kWorld || velocity == nullptr ? -off : c.rate[e] - off;
        }
        point_at(rhs, c.far) += b1 / 4.0;
        point_at(rhs, c.near) = reduced;
    }
}

void ClampedEnds::expand(double* x) const {
    for (std::size_t k = 0; k < count_; ++k) {
        const Clamp& c = clamps_[k];
        const Vec3 u = point_at(x, c.near);  // in the frame (d, e_1, e_2)
        // x_1 = (R u + x_2) / 4.
        point_at(x, c.near) = (u[0] * c.direction + u[1] * c.across[0] + u[2] * c.across[1] + point_at(x, c.far)) / 4.0;
    }
}

}  // namespace enteron::mechanics
