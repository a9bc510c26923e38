// A surgical tool as the bowel sees it: a capsule (a shaft swept by a sphere) whose tip is
// at `position` and whose shaft runs from the tip back along the orientation's local +z
// axis for `length` metres (the identity orientation is a vertical tool pointing down,
// tip lowest). Poses come from the caller (tool_mailbox.h); the tool moves continuously
// from the previous pose to the new one over the next step.
#pragma once

#include <array>
#include <cstdint>

#include "base/geometry.h"

namespace enteron::collision {

// The defaults of ent_tool_desc and of a JSON tool.
struct ToolSettings {
    double radius = 0.005;           // m, > 0
    double length = 0.3;             // m, >= 0: shaft from the tip along local +z
    double max_force = 5.0;          // N, > 0: bound of the wrench and of a grasp
    double grasp_margin = 0.005;     // m, >= 0: reach = radius + R + margin
    double grasp_stiffness = 200.0;  // N/m, > 0
    double grasp_damping = 2.0;      // N s/m, >= 0
};

struct ToolPose {
    Vec3 position = Vec3::Zero();                           // tip, m
    std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  // w x y z, unit (the ABI's order)
};

struct ToolConfig {
    ToolSettings settings;
    ToolPose pose;  // validated: a unit quaternion
};

struct ToolWrench {
    Vec3 force = Vec3::Zero();   // N, on the tool
    Vec3 torque = Vec3::Zero();  // N m, on the tool about its tip
};

// What a tool reports after each step: published in the scene's snapshot, so that any
// thread reads it without waiting for the step. A later output is one more field here.
struct ToolOutput {
    ToolWrench wrench;      // of the last accepted step (its last evaluation)
    bool grasping = false;  // a grasp holds
    uint32_t contacts = 0;  // collision spheres touching the tool in that evaluation
};

// The unit local +z axis of a unit quaternion (w x y z) in world coordinates.
inline Vec3 quaternion_z_axis(const std::array<double, 4>& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return Vec3(2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y));
}

}  // namespace enteron::collision
