// SPDX-License-Identifier: Apache-2.0
// Rigid frames that the caller moves between steps: every obstacle has one (its pose), and
// what is attached to an obstacle (a pin, the mesentery's root) moves with its frame.
//
// A pose set between steps is a target reached at the end of the next step. Within the
// step the origin moves linearly and the orientation by normalised linear interpolation
// (nlerp), so a moved organ sweeps the bowel instead of jumping through it, exactly like a
// tool (collision/tools_force.h). The velocity of a point x of the frame during the step is
// v + w x (x - o(t)), with v and w from the pose change over the step, or the velocities the
// caller gave for that step.
//
// A frame at the identity pose that does not move maps every point to itself; its users
// test identity() and skip the transform, so that scenes whose obstacles never move keep
// their bits.
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "base/state_io.h"

namespace enteron::mechanics {

struct RigidPose {
    Vec3 position = Vec3::Zero();                                    // m
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // unit
};

// A frame at one instant of a step: world = rotation * local + origin.
struct FramePlacement {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Vec3 origin = Vec3::Zero();            // m
    Vec3 linear_velocity = Vec3::Zero();   // m/s, of the origin
    Vec3 angular_velocity = Vec3::Zero();  // rad/s
    bool identity = true;                  // rotation = I, origin = 0: world = local
    bool moving = false;                   // velocities not zero
    bool kinematic = false;                // the frame has moved since it was added

    Vec3 to_world(const Vec3& local) const { return identity ? local : Vec3(rotation * local + origin); }
    Vec3 to_local(const Vec3& world) const {
        return identity ? world : Vec3(rotation.transpose() * (world - origin));
    }
    Vec3 direction_to_world(const Vec3& local) const { return identity ? local : Vec3(rotation * local); }
    // The velocity of the frame's point at world position x, m/s.
    Vec3 velocity_at(const Vec3& x) const {
        return moving ? Vec3(linear_velocity + angular_velocity.cross(x - origin)) : Vec3::Zero();
    }
};

// A frame resting at `pose`.
FramePlacement placement_at(const RigidPose& pose);

class RigidFrames {
public:
    explicit RigidFrames(std::pmr::memory_resource* memory);

    // Adds a frame resting at `pose` (unit quaternion); returns its index. Allocates.
    std::size_t add(const RigidPose& pose);
    std::size_t size() const { return frames_.size(); }

    // Between steps: the pose the next step ends at (unit quaternion).
    void set_target(std::size_t frame, const RigidPose& pose);
    // Between steps: the velocities the contact law uses during the next step instead of
    // those of the motion (m/s of the origin, rad/s).
    void set_velocity(std::size_t frame, const Vec3& linear, const Vec3& angular);
    // Where the frame rests between steps (where the last accepted step left it).
    const RigidPose& pose(std::size_t frame) const { return frames_[frame].current; }

    // Step hooks (Stepper::step, stepper.h): the step of dt seconds starting at time t0, then whether it
    // was accepted (the frames rest at their targets) or not (they stay, targets kept).
    void begin_step(double t0, double dt);
    void end_step(bool accepted);
    // Seconds of the current step (0 between steps).
    double step_length() const { return step_dt_; }

    // The frame at time t (clamped to the current step; its resting pose between steps).
    FramePlacement at(std::size_t frame, double t) const;
    // The frame at the end of the current step (its target).
    FramePlacement at_end(std::size_t frame) const;
    // True if some frame moves in the current step, or has left the identity pose: the
    // attachments that follow frames then have work to do.
    bool any_moving() const { return any_moving_; }
    bool moving(std::size_t frame) const { return frames_[frame].moving; }

    // Between steps: every frame's pose, its target and given velocity (set for the next
    // step), and whether it has moved; a section of a saved state (docs/scoring-and-state.md).
    void save_state(StateWriter& out) const;
    // The number of frames must match (the same obstacles and attachments).
    void restore_state(StateReader& in);

private:
    struct Frame {
        RigidPose current;  // at the start of the step (resting between steps)
        RigidPose target;   // at its end
        bool velocity_given = false;
        Vec3 given_linear = Vec3::Zero();
        Vec3 given_angular = Vec3::Zero();
        bool moving = false;  // in the current step
        bool identity = true;  // current and target are the identity pose
        bool kinematic = false;  // has moved in some step: moved by the caller, not fixed
    };
    FramePlacement placement(const Frame& frame, double alpha) const;

    std::pmr::vector<Frame> frames_;
    double step_start_ = 0.0;
    double step_dt_ = 0.0;
    bool any_moving_ = false;
};

// A unit quaternion (w x y z in the ABI's order) as Eigen's.
inline Eigen::Quaterniond quaternion_wxyz(double w, double x, double y, double z) {
    return Eigen::Quaterniond(w, x, y, z);
}

}  // namespace enteron::mechanics
