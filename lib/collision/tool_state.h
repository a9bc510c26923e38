// SPDX-License-Identifier: Apache-2.0
// A tool's state inside the tools effect (tools_force.h), one struct per phase of the step
// that writes it, one copy of each: what the caller commanded, what it holds, where its
// proxy is, what its last evaluation found, what the bowel received over the current
// attempt, and what the last accepted step published. Only the proxy's place is kept twice:
// as it is, and as it was at the step's start for a retry (the rollback contract of
// mechanics/stepper.h).
#pragma once

#include <cstddef>
#include <cstdint>

#include "base/geometry.h"
#include "collision/contact_model.h"
#include "collision/passivity_observer.h"
#include "collision/tool.h"
#include "collision/tool_grasp.h"
#include "spline/catmull_rom.h"

namespace enteron::collision {

// Where a tool's proxy is (tool_proxy.h): its tip, its velocity, and when it was there.
struct ProxyPlace {
    Vec3 position = Vec3::Zero();  // m
    Vec3 velocity = Vec3::Zero();  // m/s
    double time = 0.0;             // s
};

// What a tool holds (tool_grasp.h).
struct GraspHold {
    bool holding = false;
    bool slipped = false;            // in the current attempt: let go when the step is accepted
    spline::SegmentWeights point;    // the material point of the axis held
    uint32_t sphere = 0;             // the collision sphere it was when grasped
    // The spring's rest length at the step's start, m: where the held point was when
    // grasped, closing to the tool's radius plus the bowel's (grasp_rest).
    double rest = 0.0;
};

// What the tool's last evaluation found.
struct ToolEvaluation {
    std::size_t first_contact = 0;  // its contacts in the evaluation's list (tool_contacts.h)
    std::size_t contact_count = 0;  // the grasp's spring among them
    uint32_t sphere_contacts = 0;   // collision spheres touching it
    ProxyPlace rested;              // where the proxy rested (the commanded tip in direct mode)
    std::size_t body = 0;           // its border body in the implicit system, if has_body
    bool has_body = false;
    Mat3 stiffness = Mat3::Zero();  // d(force on the tool)/d(tip), N/m
    bool bounded = false;           // max_force scaled its force down
};

// What the bowel received from the tool over the current attempt, integrated over time.
struct AttemptSums {
    Vec3 impulse = Vec3::Zero();          // N s, on the bowel
    Vec3 angular_impulse = Vec3::Zero();  // N m s, on the tool about its tip
    double duration = 0.0;                // s
    Mat3 stiffness = Mat3::Zero();        // of the last evaluation used, N/m
    uint32_t contacts = 0;                // its sphere contacts
    // The impulse of the bowel's contacts (not the grasp) on the tool: the vector sum and
    // the sum of the magnitudes, N s.
    Vec3 contact_impulse = Vec3::Zero();
    double contact_impulse_magnitude = 0.0;
    double proxy_travel = 0.0;  // m, the length of the proxy's path
    bool saturated = false;     // an evaluation it used was bounded by max_force
};

// What the last accepted step published, and the sums since the tool was added.
struct AcceptedOutputs {
    ToolWrench wrench;
    Mat3 stiffness = Mat3::Zero();  // N/m
    uint32_t contacts = 0;
    PassivityObserver observer;
    Vec3 contact_impulse = Vec3::Zero();     // N s, ToolOutput's
    double contact_impulse_magnitude = 0.0;  // N s
    bool saturated = false;                  // max_force bounded the force (ToolOutput's)
};

struct ToolState {
    ToolSettings settings;
    ContactParameters contact;  // the law of its contacts: the scene's, with the tool's friction
    GraspLaw grasp_law;         // of its grasp, from its settings
    bool removed = false;
    ToolPose current;  // the commanded pose at the step's start (tool_motion.h)
    ToolPose target;   // and at its end
    // The commanded tip's velocity over the last accepted step, m/s: the proxy's coupling
    // damper takes the mean of it and this step's (tool_proxy_contacts.cpp).
    Vec3 last_tip_velocity = Vec3::Zero();
    GraspHold grasp;
    ProxyPlace proxy;           // after the last evaluation the integrator used
    ProxyPlace proxy_at_start;  // at the step's start, for a retry
    ToolEvaluation evaluation;
    AttemptSums attempt;
    AcceptedOutputs accepted;
};

}  // namespace enteron::collision
