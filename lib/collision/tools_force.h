// Contact and grasp of surgical tools (tool.h) with the bowel: every collision sphere
// against every tool's capsule with the penalty law of contact_model.h, and a grasp
// spring-damper from a material point of the axis to the tool tip. Like the environment,
// each contact touches four consecutive control points, so its linearisation goes into the
// implicit system.
//
// Motion: a new pose is a target reached at the end of the next step; within the step the
// tip moves linearly and the orientation by nlerp, so a fast tool sweeps the bowel instead
// of jumping through it. The tool's velocity (for contact damping) is the pose change over
// the step. Bound: the total force of one tool on the bowel (contacts and grasp) is scaled
// down to max_force; the wrench reported is exactly minus that force. A grasp whose spring
// alone would need more than max_force slips: it is released at the end of the step.
#pragma once

#include <memory_resource>
#include <vector>

#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/tool.h"
#include "mechanics/axis_model.h"
#include "mechanics/effect.h"

namespace enteron::collision {

struct ToolWrench {
    double force[3] = {0.0, 0.0, 0.0};   // N, on the tool
    double torque[3] = {0.0, 0.0, 0.0};  // N m, on the tool about its tip
};

class ToolsForce final : public mechanics::Effect {
public:
    ToolsForce(const mechanics::AxisModel& model, double rest_length, double radius, double sphere_spacing,
               const ContactParameters& contact, const mechanics::State& initial, std::pmr::memory_resource* memory);

    EffectId id() const override { return EffectId::tools; }
    void evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) override;
    double potential_energy(const mechanics::State& state) const override;
    void add_stiffness_bound(spline::ScalarBandMatrix& bound) const override;
    void add_damping_bound(spline::ScalarBandMatrix& bound) const override;
    void add_contacts(mechanics::ContactSummary& summary) const override;
    double external_work_bound() const override;

    // Adds a tool (validated, unit quaternion) resting at its pose. Allocates. Returns its index.
    std::size_t add_tool(const ToolConfig& tool);
    std::size_t size() const { return tools_.size(); }

    // The pose the tool reaches at the end of the next step (validated, unit quaternion).
    void set_target(std::size_t tool, const ToolPose& pose);
    // Grasps the axis point nearest the tip within reach, if any; true if one is held.
    bool grasp(std::size_t tool, const mechanics::State& state);
    void release(std::size_t tool) { tools_[tool].grasping = false; }
    bool grasping(std::size_t tool) const { return tools_[tool].grasping; }
    const ToolWrench& wrench(std::size_t tool) const { return tools_[tool].wrench; }

    // Step protocol of the scene: begin_step before the attempts, begin_attempt before each,
    // end_step after the accepted one (the tools then rest at their targets), abort_step
    // when every attempt failed (the targets stay for the next step).
    void begin_step(double start_time, double dt);
    void begin_attempt();
    void end_step();
    void abort_step();

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
    };
    struct Hit {
        std::size_t sphere;
        ContactForce force;  // on the bowel
        double normal[3];
        double depth;
        double point[3];  // contact point on the tool's surface
    };
    // Tip, back end of the shaft, and their velocities at time t.
    void segment_at(const Tool& tool, double t, double tip[3], double tail[3], double tip_v[3],
                    double tail_v[3]) const;
    double fraction_of_step(double t) const;

    mutable CollisionSpheres spheres_;
    ContactParameters contact_;
    std::pmr::vector<Tool> tools_;
    std::pmr::vector<Hit> hits_;
    double step_start_ = 0.0;
    double step_dt_ = 0.0;  // 0 between steps
    mechanics::ContactSummary last_;
};

}  // namespace enteron::collision
