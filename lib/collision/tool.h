// SPDX-License-Identifier: Apache-2.0
// A surgical tool as the bowel sees it: a capsule (a shaft swept by a sphere) whose tip is
// at `position` and whose shaft runs from the tip back along the orientation's local +z
// axis for `length` metres (the identity orientation is a vertical tool pointing down,
// tip lowest); a retractor's blade widens the first part of the shaft across local x
// (tool_shaft.h). Poses come from the caller (tool_mailbox.h); the tool moves continuously
// from the previous pose to the new one over the next step.
//
// Two modes (docs/haptics.md):
//  - proxy (the default): the capsule in the scene is a proxy (a god-object, Zilles and
//    Salisbury 1995) that the bowel's contacts keep out of the tube, joined to the
//    commanded pose by a virtual coupling (Colgate et al. 1995), a spring-damper bounded
//    by max_force. The bowel receives what the proxy gives it; the device renders the
//    coupling force (tool_proxy.h).
//  - direct: the capsule is where the caller puts it, its contacts bounded together by
//    max_force (the behaviour before the proxy).
#pragma once

#include <array>
#include <cstdint>

#include "base/geometry.h"

namespace enteron::collision {

enum class ToolMode : int32_t { proxy = 0, direct = 1 };

// The defaults of ent_tool_desc and of a JSON tool.
struct ToolSettings {
    double radius = 0.005;           // m, > 0
    double length = 0.3;             // m, >= 0: shaft from the tip along local +z
    double max_force = 5.0;          // N, > 0: bound of the wrench and of a grasp
    double grasp_margin = 0.005;     // m, >= 0: reach = radius + R + margin
    double grasp_stiffness = 200.0;  // N/m, > 0
    double grasp_damping = 2.0;      // N s/m, >= 0
    ToolMode mode = ToolMode::proxy;
    // The virtual coupling of the proxy to the commanded pose: 1 N/mm, within the stable
    // range of a Touch-class device (1 to 2.3 N/mm) at 1 kHz, and a damper of 1 N s/m, twice
    // the k T / 2 that Colgate's condition asks of a device's own damping at 1 kHz.
    double coupling_stiffness = 1000.0;  // N/m, > 0
    double coupling_damping = 1.0;       // N s/m, >= 0
    double friction = -1.0;              // Coulomb coefficient of its contacts, >= 0; < 0: the scene's
    bool passivity_limiter = false;      // Hannaford and Ryu's time-domain passivity controller
    // A grasper's jaws (grasp_aim.h): the last jaw_length metres of the shaft, opening
    // jaw_opening wide across the tool's local x axis. Both 0: a grasp takes what lies
    // nearest the tip (the first tools' rule).
    double jaw_length = 0.0;   // m, >= 0
    double jaw_opening = 0.0;  // m, >= 0
    // A retractor's blade (tool_shaft.h): the first blade_length metres of the shaft from the
    // tip widened to blade_width across the tool's local x axis, as thick as the shaft. A
    // width of 0: no blade, the capsule of a grasper.
    double blade_width = 0.0;   // m, >= 0
    double blade_length = 0.0;  // m, >= 0 (beyond `length`: the whole shaft)
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

// A tool's passivity observer and its counters since the tool was made (ent_tool_stats).
struct ToolStats {
    double largest_force_change = 0.0;  // N: the largest change of the rendered force from one step to the next
    double energy_in = 0.0;             // J: work the tool did on the scene
    double energy_out = 0.0;            // J: work the scene did on the tool (given back)
    double limiter_energy = 0.0;        // J: what the passivity limiter took out (0 when it is off)
};

// What a tool reports after each step: published in the scene's snapshot, so that any
// thread reads it without waiting for the step. A later output is one more field here.
struct ToolOutput {
    ToolWrench wrench;      // of the last accepted step: minus what the bowel received in it
    bool grasping = false;  // a grasp holds
    bool removed = false;   // the tool was removed (ent_tool_remove)
    uint32_t contacts = 0;  // collision spheres touching the tool in that evaluation
    // d(force)/d(tip position) at the last accepted step, row-major, N/m (velocities held).
    std::array<double, 9> stiffness{};
    ToolPose commanded;  // the pose the caller asked for, reached at the end of that step
    ToolPose proxy;      // where the tool is in the scene (the commanded pose in direct mode)
    ToolStats stats;
    uint32_t grasp_sphere = 0;  // while grasping: the collision sphere grasped, when the grasp took hold
    // The impulse of the bowel's contacts on the tool since it was added (what the bowel
    // received from the tool's contacts, not its grasp, over each accepted step): the vector
    // sum, N s, and the sum of the magnitudes, N s (how hard for how long, whatever the direction).
    Vec3 contact_impulse = Vec3::Zero();
    double contact_impulse_magnitude = 0.0;
    // max_force bounded the tool's force in that step (in an evaluation the step used, or
    // the wrench was clipped to it): the force is the bound, not what the contacts asked.
    bool saturated = false;
};

// The unit local +x axis of a unit quaternion (w x y z) in world coordinates.
inline Vec3 quaternion_x_axis(const std::array<double, 4>& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return Vec3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y));
}

// The unit local +z axis of a unit quaternion (w x y z) in world coordinates.
inline Vec3 quaternion_z_axis(const std::array<double, 4>& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return Vec3(2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y));
}

}  // namespace enteron::collision
