// What the render thread asks of the tools and what they felt: the small exchange between
// the render thread (the mouse) and the physics thread (the only thread that may drive the
// scene, see "Threads" in enteron.h).
//
// The render thread publishes ToolCommands (newest wins, LatestValue); the physics thread
// takes them at the start of a tick, moves each tool toward its target no faster than
// max_speed (a mouse click must not teleport a 30 cm shaft through the bowel), sets the
// pose, grasps or releases on a change of the grasp level, steps, and reads the wrench
// back. When ent_tool_set_pose, ent_tool_grasp and the wrench become callable from any
// thread (issue 16), the render thread can make those calls itself and follow() moves
// to its side; the rest of the viewer does not change.
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
    bool grasp[kMaxTools] = {};        // jaws closed (a level, not an edge)
    double max_speed_m_per_s = 1.0;    // tip speed limit toward the target
    double max_turn_rad_per_s = 3.0;   // rotation speed limit toward the target
};

// Physics thread -> render thread: a tool after the last step.
struct ToolReadback {
    ToolPose pose;                     // the pose the scene used
    double force_N[3] = {0.0, 0.0, 0.0};    // on the tool, from the bowel (ent_tool_wrench)
    double torque_Nm[3] = {0.0, 0.0, 0.0};  // about the tip
    bool grasping = false;             // ent_tool_state
};

// Moves a pose toward a target over dt_s, no faster than the given speeds; returns the
// new pose. Pure function (physics thread).
ToolPose follow(const ToolPose& from, const ToolPose& to, double dt_s, double max_speed_m_per_s,
                double max_turn_rad_per_s);

}  // namespace viewer
