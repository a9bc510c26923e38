// SPDX-License-Identifier: Apache-2.0
// A tool's commanded motion within a step (tools_force.h): a new pose is a target reached at
// the end of the step; within it the commanded tip moves linearly and the orientation by
// normalised linear interpolation (nlerp), so a fast tool sweeps the bowel instead of jumping
// through it. The shaft's velocities are the pose change over the step.
#pragma once

#include "base/geometry.h"
#include "collision/tool.h"

namespace enteron::collision {

// The step the tools move in: when it began and how long it is.
struct StepSpan {
    double start = 0.0;  // s
    double dt = 0.0;     // s; 0 between steps

    // The fraction of the step done at time t, in [0, 1] (0 between steps).
    double fraction(double t) const;
    // Seconds since the step began at time t, >= 0 (0 between steps).
    double elapsed(double t) const;
};

// A tool's shaft at one instant: its tip and back end, and their velocities; a
// retractor's blade's half width across the tool (local x, tool_shaft.h) and its velocity.
struct ShaftAt {
    Vec3 tip, tail;                    // m
    Vec3 tip_velocity, tail_velocity;  // m/s
    Vec3 side = Vec3::Zero();           // m
    Vec3 side_velocity = Vec3::Zero();  // m/s
};

// The back end of the shaft of a tool of `length` m at `pose`.
Vec3 tail_of(const ToolPose& pose, double length);

// The commanded shaft at time t of `step`, on its way from `from` (the step's start) to `to`
// (its end); at `from` between steps, at rest. A blade `half_width` wide each side.
ShaftAt commanded_shaft(const ToolPose& from, const ToolPose& to, double length, const StepSpan& step, double t,
                        double half_width = 0.0);

// The share of a tool's shaft its blade covers from the tip (Blade::along), [0, 1].
double blade_share(const ToolSettings& settings);

// How far the commanded motion from `from` to `to` carries the shaft, m: its tip, its back
// end, and its back end by the turn alone (what the shaft's turn adds to a proxy's path).
struct ShaftTravel {
    double tip;
    double tail;
    double turn;
};
ShaftTravel commanded_travel(const ToolPose& from, const ToolPose& to, double length);

}  // namespace enteron::collision
