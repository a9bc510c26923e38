// SPDX-License-Identifier: Apache-2.0
// What the render thread asks of the tools and what they felt.
//
// The tool commands of the library (ent_tool_set_pose, ent_tool_grasp, ent_tool_release)
// may be posted from any thread: the next step takes them. The viewer posts the jaws'
// changes from the render thread itself (LocalSession::send). The pose it does not: a
// mouse moves at the frame rate, 60 Hz or less, and a pose posted once a frame would
// make the tool jump within one 1 ms step and rest for the next fifteen. So the render
// thread publishes its targets (ToolCommands, newest wins) and the physics thread, like
// a haptic device's 1 kHz loop, moves each tool toward its target before every step no
// faster than max_speed (a click must not teleport a 30 cm shaft through the bowel) and
// posts that pose. After the step it reads what each tool felt, ent_tool_read_feedback,
// from the published snapshot.
#pragma once

#include <enteron/enteron.h>

#include <cstdint>

namespace viewer {

// Tools the viewer drives, draws and plots; a scene's further tools stay where they are.
inline constexpr std::uint32_t kMaxTools = 4;

struct ToolPose {
    double position_m[3] = {0.0, 0.0, 0.0};              // tip, m
    double orientation_wxyz[4] = {1.0, 0.0, 0.0, 0.0};   // unit quaternion
};

// Render thread -> physics thread.
struct ToolCommands {
    std::uint32_t count = 0;           // tools commanded, <= kMaxTools
    ToolPose target[kMaxTools];        // where each tool should go
    bool grasp[kMaxTools] = {};        // jaws closed (a level, not an edge; posted by the render thread)
    double max_speed_m_per_s = 1.0;    // tip speed limit toward the target
    double max_turn_rad_per_s = 3.0;   // rotation speed limit toward the target
};

// Physics thread -> render thread: a tool after the last step.
struct ToolReadback {
    ToolPose pose;                     // the pose posted for that step
    ent_tool_feedback feedback{};      // force, torque, grasp, contacts (ent_tool_read_feedback)
};

// Moves a pose toward a target over dt_s, no faster than the given speeds; returns the
// new pose. Pure function (physics thread).
ToolPose follow(const ToolPose& from, const ToolPose& to, double dt_s, double max_speed_m_per_s,
                double max_turn_rad_per_s);

}  // namespace viewer
