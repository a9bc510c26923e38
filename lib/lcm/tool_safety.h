// SPDX-License-Identifier: Apache-2.0
// The safety rules of one tool, applied at every tick (docs/lcm.md, "Safety"):
// - a command older than the watchdog time on the bridge's own clock makes the tool stale:
//   zero force, the tool held where it was (never judged by comparing two hosts' clocks);
// - the tool moves toward the commanded pose at a bounded speed and turning rate, so a
//   command that jumps (or one that comes back after a stop) never teleports the tool;
// - after any stop of the force (no command yet, stale, deadman released, a failed step)
//   the force ramps back in linearly over force_ramp_s, so it never comes back as a jolt;
// - the force is clamped to the tool's max_force, then (device units) to the device's
//   limit, and its change per tick may be limited; a stop to zero is never delayed;
// - grasp is a level: the scene is told to grasp or release only when the commanded level
//   differs from the one it last acted on.
// Pure logic: no scene, no clock, no allocation; the tick feeds it and the tests drive it.
#pragma once

#include <cstdint>

#include "lcm/workspace_mapping.h"

namespace enteron::lcm {

// A command that passed every check of the receive thread, mapped into the scene.
struct AcceptedCommand {
    int64_t seq = -1;
    int64_t utime = 0;        // the sender's, as sent
    int64_t received_ns = 0;  // the bridge's monotonic clock when it arrived
    Pose scene_pose;          // mapped into the scene, orientation unit
    bool grasp = false;
    bool force_enable = false;
};

struct SafetyLimits {
    double tick_s = 0.001;
    int64_t watchdog_ns = 30000000;
    double force_ramp_s = 0.1;
    double max_speed_m_per_s = 1.0;             // scene frame
    double max_angular_speed_rad_per_s = 10.0;
    double tool_max_force_N = 5.0;              // scene newtons
    double device_max_force = 0.0;              // device units; 0: none
    double max_force_change_per_tick = 0.0;     // device units; 0: none
};

// The status bits of tool_feedback_t (bindings/lcm/tool_feedback_t.lcm).
enum StatusBit : int32_t {
    kStale = 1,
    kNoCommand = 2,
    kForceLimited = 4,
    kRateLimited = 8,
    kUnstable = 16,
    kForceDisabled = 32,
    kCommandsRejected = 64,  // with the reason (REJECTED_*) in bits 8-15: rejection_status()
};

// The grasp call to make before the step (journal_tool_t GRASP_*).
enum class GraspAction : int8_t { none = 0, grasp = 1, release = 2 };

class ToolSafety {
public:
    ToolSafety(const SafetyLimits& limits, const WorkspaceMapping& mapping, const Pose& initial_pose);

    struct Plan {
        GraspAction grasp_action = GraspAction::none;
        bool watchdog_tripped = false;  // the tool went stale at this tick
    };
    // Before the step. `fresh` is a command newer than the last one, or nullptr. Updates
    // the pose to give the scene (applied_pose()).
    Plan plan(const AcceptedCommand* fresh, int64_t now_ns);

    // After the step: what the device renders, from the bowel's force and torque on the
    // tool and its stiffness (scene frame). saturated: the library bounded that force at the
    // tool's max_force (ent_tool_feedback.saturated). step_ok: the step succeeded.
    void render(const Eigen::Vector3d& scene_force_N, const Eigen::Vector3d& scene_torque_Nm,
                const Eigen::Matrix3d& scene_stiffness_N_per_m, bool saturated, bool step_ok);

    const Pose& applied_pose() const { return applied_; }
    // The newest accepted command's pose (scene frame), the initial pose before any.
    const Pose& commanded_pose() const { return has_command_ ? latest_.scene_pose : applied_; }
    bool live() const { return has_command_ && !stale_; }   // a fresh command drives the tool
    const AcceptedCommand& latest() const { return latest_; }
    int64_t command_age_ns() const { return command_age_ns_; }
    bool jaws_closed() const { return jaws_closed_; }
    int32_t status() const { return status_; }

    // What render() produced: device frame and units, and the rendered force in the scene frame.
    const Eigen::Vector3d& device_force() const { return device_force_; }
    const Eigen::Vector3d& device_torque() const { return device_torque_; }
    const Eigen::Matrix3d& device_stiffness() const { return device_stiffness_; }
    const Eigen::Vector3d& rendered_scene_force() const { return rendered_scene_force_; }
    double ramp() const { return ramp_; }

private:
    bool move_toward(const Pose& target);

    SafetyLimits limits_;
    const WorkspaceMapping* mapping_;
    Pose applied_;
    AcceptedCommand latest_;
    bool has_command_ = false;
    bool stale_ = false;
    bool jaws_closed_ = false;
    int64_t command_age_ns_ = 0;
    int32_t status_ = kNoCommand;
    double ramp_ = 0.0;  // 0 to 1: the share of the force rendered
    Eigen::Vector3d device_force_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d device_torque_ = Eigen::Vector3d::Zero();
    Eigen::Matrix3d device_stiffness_ = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rendered_scene_force_ = Eigen::Vector3d::Zero();
};

}  // namespace enteron::lcm
