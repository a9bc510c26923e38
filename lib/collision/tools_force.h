// Contact and grasp of surgical tools (tool.h) with the bowel: every collision sphere
// against every tool's capsule with the penalty law of contact_model.h, and a grasp
// spring-damper from a material point of the axis to the tool tip. Like the environment,
// each contact touches four consecutive control points, so its linearisation goes into the
// implicit system.
//
// Commands: at the start of each step (begin_step) each tool takes what its mailbox holds
// (tool_channels.h): a new pose, a grasp or a release. At the end (end_step) it writes its
// output (wrench, grasp, contacts) for the scene to publish.
//
// Motion: a new pose is a target reached at the end of the step; within the step the
// tip moves linearly and the orientation by nlerp, so a fast tool sweeps the bowel instead
// of jumping through it. The tool's velocity (for contact damping) is the pose change over
// the step. Bound: the total force of one tool on the bowel (contacts and grasp) is scaled
// down to max_force; the wrench reported is exactly minus that force. A grasp whose spring
// alone would need more than max_force slips: it is released at the end of the step.
#pragma once

#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/tool.h"
#include "collision/tool_channels.h"
#include "mechanics/axis_model.h"
#include "mechanics/effect.h"

namespace enteron::collision {

class ToolsForce final : public mechanics::Effect {
public:
    // `spheres` are shared with the other contact effects and `channels` connect the tools
    // with the caller's threads; both must outlive this effect.
    ToolsForce(CollisionSpheres& spheres, const ContactParameters& contact, const mechanics::State& initial,
               ToolChannels& channels, std::pmr::memory_resource* memory);

    mechanics::EffectId id() const override { return mechanics::EffectId::tools; }
    void evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) override;
    double potential_energy(const mechanics::State& state) const override;
    void add_stiffness_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_damping_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_contacts(mechanics::ContactSummary& summary) const override;
    double external_work_bound() const override;

    // Takes each tool's commands (a grasp picks the axis point nearest the tip, within
    // reach, as the tool rests); true if a grasp or release was made. The tools then move
    // towards their targets over the dt seconds of the step.
    bool begin_step(const mechanics::State& state, double dt) override;
    void begin_attempt() override;
    // Accepted: the tools rest at their targets and a slipped grasp is let go. Not: the
    // targets stay for the next step. Either way each tool's output is written.
    void end_step(bool accepted) override;

    // Adds a tool (validated, unit quaternion) resting at its pose, with its channels.
    // Allocates. Returns its index.
    std::size_t add_tool(const ToolConfig& tool);
    std::size_t size() const { return tools_.size(); }

private:
    struct Tool {
        ToolSettings settings;
        ToolPose current;  // where the tool rests between steps
        ToolPose target;   // where the next step takes it
        bool grasping = false;
        bool slipped = false;                // in the current attempt
        spline::SegmentWeights grasp_point;  // material point of the axis held
        ToolWrench wrench;                   // of the last accepted step
        ToolWrench attempt_wrench;           // of the last evaluation
        uint32_t contacts = 0;               // of the last accepted step
        uint32_t attempt_contacts = 0;       // of the last evaluation
    };
    struct Hit {
        std::size_t sphere;
        ContactForce force;  // on the bowel
        Vec3 normal;
        double depth;
        Vec3 point;  // contact point on the tool's surface
    };
    // A tool's shaft at one instant: its tip and back end, and their velocities.
    struct Segment {
        Vec3 tip, tail;                    // m
        Vec3 tip_velocity, tail_velocity;  // m/s
    };
    Segment segment_at(const Tool& tool, double t) const;
    double fraction_of_step(double t) const;
    // Grasps the axis point nearest the tip within reach, if any.
    void grasp(Tool& tool, const mechanics::State& state);

    CollisionSpheres& spheres_;  // shared with the other contact effects
    ToolChannels& channels_;
    ContactParameters contact_;
    std::pmr::vector<Tool> tools_;
    std::pmr::vector<Hit> hits_;
    double step_start_ = 0.0;
    double step_dt_ = 0.0;  // 0 between steps
    mechanics::ContactSummary last_;
};

}  // namespace enteron::collision
