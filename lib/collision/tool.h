// A surgical tool as the bowel sees it: a capsule (a shaft swept by a sphere) whose tip is
// at `position` and whose shaft runs from the tip back along the orientation's local +z
// axis for `length` metres (the identity orientation is a vertical tool pointing down,
// tip lowest). Poses are set by the caller between steps; the tool moves continuously
// from the previous pose to the new one over the next step.
#pragma once

#include <array>
#include <cmath>
#include <string>

#include "base/error.h"

namespace enteron::collision {

struct ToolSettings {
    double radius = 0.005;           // m, > 0
    double length = 0.3;             // m, >= 0: shaft from the tip along local +z
    double max_force = 5.0;          // N, > 0: bound of the wrench and of a grasp
    double grasp_margin = 0.005;     // m, >= 0: reach = radius + R + margin
    double grasp_stiffness = 200.0;  // N/m, > 0
    double grasp_damping = 2.0;      // N s/m, >= 0
};

struct ToolPose {
    std::array<double, 3> position{};                  // tip, m
    std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  // w x y z, unit
};

struct ToolConfig {
    ToolSettings settings;
    ToolPose pose;
};

// The unit local +z axis of a unit quaternion (w x y z) in world coordinates.
inline std::array<double, 3> quaternion_z_axis(const std::array<double, 4>& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return {2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y)};
}

// Checks a pose and returns it with a unit quaternion. Throws Error(code) naming `name`
// for a non-finite position or a zero or non-finite quaternion.
ToolPose normalized_pose(const ToolPose& pose, const std::string& name, ErrorCode code);

// Checks the settings; throws Error(code) naming the field ("tools[1].radius must be > 0").
void validate_tool_settings(const ToolSettings& settings, const std::string& name, ErrorCode code);

}  // namespace enteron::collision
