// SPDX-License-Identifier: Apache-2.0
#include "mechanics/pinned_points.h"

#include <algorithm>
#include <cmath>

#include "base/state_io.h"
#include "mechanics/bordered_system.h"

namespace enteron::mechanics {

PinnedPoints::PinnedPoints(const std::vector<uint32_t>& points, const RigidFrames& frames, double max_speed,
                           std::pmr::memory_resource* memory)
    : frames_(frames), speed_limit_(0.5 * max_speed), points_(points.begin(), points.end(), memory), attached_(memory) {
    std::sort(points_.begin(), points_.end());
    points_.erase(std::unique(points_.begin(), points_.end()), points_.end());
}

void PinnedPoints::evaluate(const State& state, double* force, const Linearization* lin) {
    // The power of the attached points on the rest of the bowel: the forces on their rows,
    // which the constraint takes over, times their velocities.
    double power = 0.0;
    for (const Attachment& a : attached_)
        power += point_at(force, a.point).norm() * point_at(state.v.data(), a.point).norm();
    largest_power_ = std::max(largest_power_, power);
    zero_rows(force);
    if (lin != nullptr) {
        constrain(*lin->system);
        zero_rows(lin->stiffness_times_velocity);
        if (lin->border != nullptr)
            for (uint32_t p : points_)
                for (std::size_t c = 0; c < 3; ++c) lin->border->zero_row(3 * std::size_t{p} + c);
    }
}

void PinnedPoints::begin_step(double dt) {
    step_dt_ = dt;
    largest_power_ = 0.0;
}

void PinnedPoints::pin(uint32_t point, std::size_t frame, State& state) {
    const Vec3 position = point_at(state.q.data(), point);
    const auto at = std::lower_bound(points_.begin(), points_.end(), point);
    attached_.reserve(attached_.size() + 1);
    if (at == points_.end() || *at != point) points_.insert(at, point);
    attached_.erase(std::remove_if(attached_.begin(), attached_.end(), [&](const Attachment& a) { return a.point == point; }),
                    attached_.end());
    if (frame != kWorld) attached_.push_back({point, frame, frames_.at(frame, state.time).to_local(position)});
    point_at(state.v.data(), point).setZero();
}

bool PinnedPoints::unpin(uint32_t point) {
    const auto at = std::lower_bound(points_.begin(), points_.end(), point);
    if (at == points_.end() || *at != point) return false;
    points_.erase(at);
    attached_.erase(std::remove_if(attached_.begin(), attached_.end(), [&](const Attachment& a) { return a.point == point; }),
                    attached_.end());
    return true;
}

bool PinnedPoints::pinned(uint32_t point) const { return std::binary_search(points_.begin(), points_.end(), point); }

bool PinnedPoints::prescribe(State& state, double dt) const {
    bool moving = false;
    for (const Attachment& a : attached_) {
        const Vec3 target = frames_.at_end(a.frame).to_world(a.local);
        Vec3 velocity = (target - point_at(state.q.data(), a.point)) / dt;
        const double speed = velocity.norm();
        if (speed > speed_limit_) velocity *= speed_limit_ / speed;
        point_at(state.v.data(), a.point) = velocity;
        moving = moving || speed > 0.0;
    }
    return moving;
}

void PinnedPoints::constrain(numerics::ScalarBandMatrix& per_point) const {
    for (uint32_t p : points_) per_point.make_identity_row(p);
}

void PinnedPoints::constrain(SystemMatrix& system) const {
    for (uint32_t p : points_)
        for (std::size_t c = 0; c < 3; ++c) system.make_identity_row(3 * std::size_t{p} + c);
}

void PinnedPoints::zero_rows(double* values) const {
    for (uint32_t p : points_)
        for (std::size_t c = 0; c < 3; ++c) values[3 * std::size_t{p} + c] = 0.0;
}

void PinnedPoints::save_state(StateWriter& out) const {
    out.begin_section("pins", 1);
    out.u32(static_cast<uint32_t>(points_.size()));
    out.u32s(points_.data(), points_.size());
    out.u32(static_cast<uint32_t>(attached_.size()));
    for (const Attachment& a : attached_) {
        out.u32(a.point);
        out.u32(static_cast<uint32_t>(a.frame));
        out.f64s(a.local.data(), 3);
    }
    out.end_section();
}

void PinnedPoints::restore_state(StateReader& in, std::size_t control_points) {
    in.begin_section("pins", 1);
    std::pmr::vector<uint32_t> points(points_.get_allocator());
    points.resize(in.count("pinned points", control_points));
    for (uint32_t& p : points) p = in.index("pinned point", control_points);
    for (std::size_t k = 1; k < points.size(); ++k)
        if (!(points[k - 1] < points[k])) in.fail("the pinned points are not in ascending order");
    std::pmr::vector<Attachment> attached(attached_.get_allocator());
    attached.resize(in.count("attached points", points.size()));
    for (Attachment& a : attached) {
        a.point = in.index("attached point", control_points);
        if (!std::binary_search(points.begin(), points.end(), a.point)) in.fail("an attached point is not pinned");
        a.frame = in.index("frame of an attached point", frames_.size());
        in.f64s("attached point in its frame", 3, a.local.data());
    }
    in.end_section();
    if (in.checking()) return;
    points_ = std::move(points);
    attached_ = std::move(attached);
}

}  // namespace enteron::mechanics
