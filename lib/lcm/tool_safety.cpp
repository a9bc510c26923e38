// SPDX-License-Identifier: Apache-2.0
#include "lcm/tool_safety.h"

#include <algorithm>
#include <cmath>

namespace enteron::lcm {

ToolSafety::ToolSafety(const SafetyLimits& limits, const WorkspaceMapping& mapping, const Pose& initial_pose)
    : limits_(limits), mapping_(&mapping), applied_(initial_pose) {}

ToolSafety::Plan ToolSafety::plan(const AcceptedCommand* fresh, int64_t now_ns) {
    Plan plan;
    if (fresh != nullptr) {
        latest_ = *fresh;
        has_command_ = true;
    }
    command_age_ns_ = has_command_ ? now_ns - latest_.received_ns : 0;
    const bool stale = has_command_ && command_age_ns_ > limits_.watchdog_ns;
    plan.watchdog_tripped = stale && !stale_;
    stale_ = stale;

    status_ = 0;
    if (!has_command_) status_ |= kNoCommand;
    if (stale_) status_ |= kStale;
    // Stale or no command: the tool stays where it is (the target is the applied pose).
    if (live() && move_toward(latest_.scene_pose)) status_ |= kRateLimited;
    if (live() && latest_.grasp != jaws_closed_) {
        jaws_closed_ = latest_.grasp;
        plan.grasp_action = jaws_closed_ ? GraspAction::grasp : GraspAction::release;
    }
    return plan;
}

// Moves the applied pose toward the target by at most one tick of the bounded speeds;
// true if a bound held it back.
bool ToolSafety::move_toward(const Pose& target) {
    bool limited = false;
    const Eigen::Vector3d step = target.position - applied_.position;
    const double distance = step.norm();
    const double reach = limits_.max_speed_m_per_s * limits_.tick_s;
    if (distance > reach) {
        applied_.position += (reach / distance) * step;
        limited = true;
    } else {
        applied_.position = target.position;
    }
    const double angle = applied_.orientation.angularDistance(target.orientation);  // in [0, pi], either sign of q
    const double turn = limits_.max_angular_speed_rad_per_s * limits_.tick_s;
    if (angle > turn) {
        applied_.orientation = applied_.orientation.slerp(turn / angle, target.orientation).normalized();
        limited = true;
    } else {
        applied_.orientation = target.orientation;
    }
    return limited;
}

void ToolSafety::render(const Eigen::Vector3d& scene_force_N, const Eigen::Vector3d& scene_torque_Nm,
                        const Eigen::Matrix3d& scene_stiffness_N_per_m, bool saturated, bool step_ok) {
    if (!step_ok) status_ |= kUnstable;
    if (live() && !latest_.force_enable) status_ |= kForceDisabled;
    const bool force_allowed = live() && latest_.force_enable && step_ok;
    if (!force_allowed) {
        // A stop is immediate, whatever the change limit; the ramp starts over.
        ramp_ = 0.0;
        device_force_.setZero();
        device_torque_.setZero();
        device_stiffness_.setZero();
        rendered_scene_force_.setZero();
        return;
    }
    ramp_ = limits_.force_ramp_s > 0.0 ? std::min(1.0, ramp_ + limits_.tick_s / limits_.force_ramp_s) : 1.0;

    // Every bound scales the force, its torque and its stiffness by one factor, so the
    // device renders the same direction and a consistent local model.
    double gain = ramp_;
    // The library bounds the force at max_force itself (ent_tool_feedback.saturated): the
    // force it reports is then exactly max_force, which the test below does not catch.
    if (saturated) status_ |= kForceLimited;
    const double scene_magnitude = ramp_ * scene_force_N.norm();
    if (scene_magnitude > limits_.tool_max_force_N) {
        gain *= limits_.tool_max_force_N / scene_magnitude;
        status_ |= kForceLimited;
    }
    Eigen::Vector3d device_force = mapping_->force_to_device(gain * scene_force_N);
    const double device_magnitude = device_force.norm();
    if (limits_.device_max_force > 0.0 && device_magnitude > limits_.device_max_force) {
        const double scale = limits_.device_max_force / device_magnitude;
        gain *= scale;
        device_force *= scale;
        status_ |= kForceLimited;
    }
    if (limits_.max_force_change_per_tick > 0.0) {
        const Eigen::Vector3d change = device_force - device_force_;
        const double change_magnitude = change.norm();
        if (change_magnitude > limits_.max_force_change_per_tick) {
            device_force = device_force_ + (limits_.max_force_change_per_tick / change_magnitude) * change;
            status_ |= kForceLimited;
        }
    }
    device_force_ = device_force;
    device_torque_ = mapping_->torque_to_device(gain * scene_torque_Nm);
    device_stiffness_ = mapping_->stiffness_to_device(gain * scene_stiffness_N_per_m);
    rendered_scene_force_ = mapping_->force_to_scene(device_force_);
}

}  // namespace enteron::lcm
