// SPDX-License-Identifier: Apache-2.0
// Contact and grasp of surgical tools (tool.h) with the bowel: every collision sphere
// against every tool's capsule with the penalty law of contact_model.h, and a grasp
// spring-damper from a material point of the axis to the tool's tip (tool_grasp.h). Like the
// environment, each contact touches four consecutive control points, so its linearisation
// goes into the implicit system.
//
// The tools are driven from outside (mechanics/driven_effect.h), and each phase of their step
// has its own file:
//  - commands: at the start of each step (take_commands) each tool takes what its mailbox
//    holds (tool_channels.h): a new pose, a grasp (the axis point nearest the tip, within
//    reach) or a release;
//  - motion: the commanded pose is reached at the end of the step, the tool sweeping
//    between the two (tool_motion.h);
//  - contacts: at each evaluation, by the tool's mode, the direct law (tool_direct_contacts.h)
//    or the proxy's (tool_proxy_contacts.h), both into one list (tool_contacts.h);
//  - outputs: the integrator tells the effect how it used each evaluation (evaluation_used),
//    the tools add up what the bowel received, and an accepted step (end_step) makes that
//    their outputs (tool_outputs.h) for the scene to publish;
//  - save and restore (tools_state.cpp).
// Each tool's state, phase by phase, is a ToolState (tool_state.h).
#pragma once

#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/collision_spheres.h"
#include "collision/contact_log.h"
#include "collision/contact_model.h"
#include "collision/tool.h"
#include "collision/tool_channels.h"
#include "collision/tool_contacts.h"
#include "collision/tool_direct_contacts.h"
#include "collision/tool_motion.h"
#include "collision/tool_proxy_contacts.h"
#include "collision/tool_state.h"
#include "mechanics/bordered_system.h"
#include "mechanics/driven_effect.h"

namespace enteron::collision {

class ToolsForce final : public mechanics::DrivenEffect {
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
    // The proxies' work in the last step and their unbalanced solves so far (ProxyWork).
    void add_work(mechanics::StepWork& work) const override;
    double external_work_bound() const override;

    // Takes each tool's commands (a grasp picks the axis point nearest the tip, within
    // reach, as the tool rests); true if a grasp or release was made. The tools then move
    // towards their targets over the dt seconds of the step.
    bool take_commands(const mechanics::State& state, double dt) override;
    // Each attempt starts with the proxies where the step began and no sums.
    void begin_attempt() override;
    // Adds what the bowel received from the last evaluation to each tool's sums; the proxy
    // moves on to where it left it.
    void evaluation_used(double duration, const mechanics::State* after) override;
    std::size_t border_bodies() const override;
    // Accepted: the tools rest at their targets, a slipped grasp is let go and the sums of
    // the step become the outputs. Not: the targets stay for the next step. Either way each
    // tool's output is written.
    void end_step(bool accepted) override;
    // The tools' poses, grasps, proxies, passivity observers, outputs and impulses, and the
    // contacts of the last evaluation used (tools_state.cpp).
    void save_state(StateWriter& out) const override;
    void restore_state(StateReader& in) override;

    // The contacts of the last evaluation the integrator used, tool by tool, with the force
    // the bowel received over it (what the wrench adds up); `other` is the tool's index.
    const ContactLog& contact_log() const { return log_; }

    // Adds a tool (validated, unit quaternion) resting at its pose, with its channels.
    // Allocates. Returns its index.
    std::size_t add_tool(const ToolConfig& tool);
    // Removes tool `index` (it must exist and not be removed yet): it lets go of what it
    // holds, touches nothing from the next step on and its output says removed. Its index
    // is not reused.
    void remove_tool(std::size_t index);
    std::size_t size() const { return tools_.size(); }

    // Tool `index`'s stiffness at its last evaluation, d(force on the tool)/d(tip) (N/m):
    // what the last accepted step publishes. For tests: an evaluation, then this.
    const Mat3& last_stiffness(std::size_t index) const { return tools_[index].evaluation.stiffness; }
    // Tool `index`'s force on the tool at its last evaluation, with the bowel as it was (N).
    Vec3 last_force(std::size_t index) const;

private:
    // The grasp spring's rest length of `tool` at time t of the step, m.
    double grasp_rest_at(const ToolState& tool, double t) const;
    // Where the grasp's spring closes to: the tool's radius plus the held sphere's.
    double grasp_surface(const ToolState& tool) const;
    // Grasps the axis point whose surface is nearest the tip (the proxy's in proxy mode),
    // within grasp_margin of the tool's, if any.
    void take_grasp(ToolState& tool, const mechanics::State& state);

    CollisionSpheres& spheres_;  // shared with the other contact effects
    ToolChannels& channels_;
    ContactParameters contact_;
    std::pmr::vector<ToolState> tools_;
    ToolContacts contacts_;  // every tool's, of the last evaluation
    DirectContacts direct_;
    ProxyContacts proxy_;
    const mechanics::BorderedSystem* border_ = nullptr;  // of the last evaluation, if implicit
    StepSpan step_;                                      // its dt is 0 between steps
    mechanics::ContactSummary last_;                     // of the last evaluation
    ContactLog log_;
};

}  // namespace enteron::collision
