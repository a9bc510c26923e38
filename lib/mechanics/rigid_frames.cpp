// SPDX-License-Identifier: Apache-2.0
#include "mechanics/rigid_frames.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace enteron::mechanics {

namespace {

bool is_identity(const RigidPose& pose) {
    return pose.position == Vec3::Zero() && pose.orientation.w() == 1.0 && pose.orientation.vec() == Vec3::Zero();
}

// Normalised linear interpolation of unit quaternions along the shorter arc (as the tools').
Eigen::Quaterniond nlerp(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double t) {
    const double sign = a.coeffs().dot(b.coeffs()) < 0.0 ? -1.0 : 1.0;
    Eigen::Quaterniond q;
    q.coeffs() = (1.0 - t) * a.coeffs() + (t * sign) * b.coeffs();
    return q.normalized();
}

// The constant angular velocity (rad/s) that turns `from` into `to` in dt seconds.
Vec3 angular_velocity(const Eigen::Quaterniond& from, const Eigen::Quaterniond& to, double dt) {
    Eigen::Quaterniond turn = to * from.conjugate();
    if (turn.w() < 0.0) turn.coeffs() = -turn.coeffs();  // the shorter way round
    const double sine = turn.vec().norm();
    if (!(sine > 0.0)) return Vec3::Zero();
    const double angle = 2.0 * std::atan2(sine, turn.w());
    return (angle / (sine * dt)) * turn.vec();
}

}  // namespace

FramePlacement placement_at(const RigidPose& pose) {
    FramePlacement p;
    if (is_identity(pose)) return p;
    p.identity = false;
    p.rotation = pose.orientation.toRotationMatrix();
    p.origin = pose.position;
    return p;
}

RigidFrames::RigidFrames(std::pmr::memory_resource* memory) : frames_(memory) {}

std::size_t RigidFrames::add(const RigidPose& pose) {
    Frame frame;
    frame.current = frame.target = pose;
    frame.identity = is_identity(pose);
    frames_.push_back(frame);
    return frames_.size() - 1;
}

void RigidFrames::set_target(std::size_t frame, const RigidPose& pose) { frames_[frame].target = pose; }

void RigidFrames::set_velocity(std::size_t frame, const Vec3& linear, const Vec3& angular) {
    Frame& f = frames_[frame];
    f.velocity_given = true;
    f.given_linear = linear;
    f.given_angular = angular;
}

void RigidFrames::begin_step(double t0, double dt) {
    step_start_ = t0;
    step_dt_ = dt;
    any_moving_ = false;
    for (Frame& f : frames_) {
        const bool displaced = f.target.position != f.current.position ||
                               f.target.orientation.coeffs() != f.current.orientation.coeffs();
        f.moving = displaced || (f.velocity_given && (f.given_linear != Vec3::Zero() || f.given_angular != Vec3::Zero()));
        f.identity = !f.moving && is_identity(f.current);
        f.kinematic = f.kinematic || f.moving;
        any_moving_ = any_moving_ || f.moving || !f.identity;
    }
}

void RigidFrames::end_step(bool accepted) {
    for (Frame& f : frames_) {
        if (accepted) {
            f.current = f.target;
            f.velocity_given = false;
        }
        f.moving = false;
        f.identity = is_identity(f.current) && is_identity(f.target);
    }
    step_dt_ = 0.0;
}

FramePlacement RigidFrames::placement(const Frame& f, double alpha) const {
    FramePlacement p;
    p.kinematic = f.kinematic;
    if (f.identity) return p;
    p.identity = false;
    const Eigen::Quaterniond q = alpha <= 0.0 ? f.current.orientation
                                 : alpha >= 1.0 ? f.target.orientation
                                                : nlerp(f.current.orientation, f.target.orientation, alpha);
    p.rotation = q.toRotationMatrix();
    p.origin = (1.0 - alpha) * f.current.position + alpha * f.target.position;
    if (f.moving && step_dt_ > 0.0) {
        p.moving = true;
        if (f.velocity_given) {
            p.linear_velocity = f.given_linear;
            p.angular_velocity = f.given_angular;
        } else {
            p.linear_velocity = (f.target.position - f.current.position) / step_dt_;
            p.angular_velocity = angular_velocity(f.current.orientation, f.target.orientation, step_dt_);
        }
    }
    return p;
}

FramePlacement RigidFrames::at(std::size_t frame, double t) const {
    const double alpha = step_dt_ > 0.0 ? std::clamp((t - step_start_) / step_dt_, 0.0, 1.0) : 0.0;
    return placement(frames_[frame], alpha);
}

FramePlacement RigidFrames::at_end(std::size_t frame) const { return placement(frames_[frame], 1.0); }

namespace {

void save_pose(StateWriter& out, const RigidPose& pose) {
    out.f64s(pose.position.data(), 3);
    out.f64s(pose.orientation.coeffs().data(), 4);  // x y z w
}

void restore_pose(StateReader& in, const char* what, RigidPose& pose) {
    in.f64s(what, 3, pose.position.data());
    in.f64s(what, 4, pose.orientation.coeffs().data());
    if (!(std::fabs(pose.orientation.norm() - 1.0) <= 1e-9))
        in.fail(std::string(what) + ": the orientation is not a unit quaternion");
}

}  // namespace

void RigidFrames::save_state(StateWriter& out) const {
    out.begin_section("frames", 1);
    out.u32(static_cast<uint32_t>(frames_.size()));
    for (const Frame& f : frames_) {
        save_pose(out, f.current);
        save_pose(out, f.target);
        out.u8(f.velocity_given ? 1 : 0);
        out.f64s(f.given_linear.data(), 3);
        out.f64s(f.given_angular.data(), 3);
        out.u8(f.moving ? 1 : 0);
        out.u8(f.identity ? 1 : 0);
        out.u8(f.kinematic ? 1 : 0);
    }
    out.u8(any_moving_ ? 1 : 0);
    out.end_section();
}

void RigidFrames::restore_state(StateReader& in) {
    in.begin_section("frames", 1);
    if (in.u32("frames") != frames_.size())
        in.fail("saved with another number of frames (obstacles and attachments made at run time)");
    for (Frame& frame : frames_) {
        Frame f;
        restore_pose(in, "frame pose", f.current);
        restore_pose(in, "frame target pose", f.target);
        f.velocity_given = in.flag("frame velocity given");
        in.f64s("frame velocity", 3, f.given_linear.data());
        in.f64s("frame angular velocity", 3, f.given_angular.data());
        f.moving = in.flag("frame moving");
        f.identity = in.flag("frame at the identity");
        f.kinematic = in.flag("frame kinematic");
        if (!in.checking()) frame = f;
    }
    const bool any_moving = in.flag("frames moving");
    in.end_section();
    if (!in.checking()) any_moving_ = any_moving;
}

}  // namespace enteron::mechanics
