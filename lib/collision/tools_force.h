// Contact and grasp of surgical tools (tool.h) with the bowel: every collision sphere
// against every tool's capsule with the penalty law of contact_model.h, and a grasp
// spring-damper from a material point of the axis to the tool's tip. Like the environment,
// each contact touches four consecutive control points, so its linearisation goes into the
// implicit system.
//
// Commands: at the start of each step (take_commands) each tool takes what its mailbox holds
// (tool_channels.h): a new pose, a grasp or a release. At the end (end_step) it writes its
// output (wrench, grasp, contacts, stiffness, poses, passivity) for the scene to publish.
//
// Motion: a new pose is a target reached at the end of the step; within the step the
// commanded tip moves linearly and the orientation by nlerp, so a fast tool sweeps the
// bowel instead of jumping through it.
//
// The two modes of tool.h:
//  - direct: the capsule is at the commanded pose, its velocity (for contact damping and
//    friction) the pose change over the step. The total force of one tool on the bowel
//    (contacts and grasp) is scaled down to max_force; a grasp whose spring alone would
//    need more than max_force slips (released at the end of the step).
//  - proxy: the capsule is the tool's proxy (tool_proxy.h), solved at each evaluation from
//    where it was, with the bowel as it is, and then moving with the bowel through the
//    implicit step: its three unknowns join the implicit system's border
//    (bordered_system.h), so the bowel receives exactly the coupling force of the
//    evaluation, spread over the contacts as the proxy's balance spreads it. A grasp
//    slips when the coupling has to pull harder than max_force to hold it.
//
// The wrench: the integrator tells the effect how it used each evaluation
// (evaluation_used), and the wrench reported for the step is exactly minus what the bowel
// received over it: the time average of the forces at the end of each implicit substep
// (F - H dq - C dv, H and C the contacts' linearisation) or of the explicit evaluations
// with their weights. Evaluating the law again at the start-of-step velocities instead
// reported a friction the bowel never received: the click at every reversal (issue 18).
#pragma once

#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/collision_spheres.h"
#include "collision/contact_log.h"
#include "collision/contact_model.h"
#include "collision/passivity_observer.h"
#include "collision/tool.h"
#include "collision/tool_channels.h"
#include "collision/tool_proxy.h"
#include "mechanics/axis_model.h"
#include "mechanics/bordered_system.h"
#include "mechanics/driven_effect.h"

namespace enteron::collision {

class ToolsForce final : public mechanics::DrivenEffect {
public:
    // How fast a grasp draws the held point in to the tool's surface, m/s: a grasp taken
    // from a distance starts slack (no jolt for the device) and tightens by at most
    // grasp_stiffness x 0.05 mm a millisecond (docs/haptics.md, "Force continuity").
    static constexpr double kGraspClosingSpeed = 0.05;
    // `spheres` are shared with the other contact effects and `channels` connect the tools
    // with the caller's threads; both must outlive this effect.
    ToolsForce(CollisionSpheres& spheres, const ContactParameters& contact, const mechanics::State& initial,
               ToolChannels& channels, std::pmr::memory_resource* memory);

    mechanics::EffectId id() const override { return mechanics::EffectId::tools; }
    void evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) override;
    void evaluation_used(double duration, const mechanics::State* after) override;
    std::size_t border_bodies() const override;
    double potential_energy(const mechanics::State& state) const override;
    void add_stiffness_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_damping_bound(numerics::ScalarBandMatrix& bound) const override;
    void add_contacts(mechanics::ContactSummary& summary) const override;
    double external_work_bound() const override;

    // Takes each tool's commands (a grasp picks the axis point nearest the tip, within
    // reach, as the tool rests); true if a grasp or release was made. The tools then move
    // towards their targets over the dt seconds of the step.
    bool take_commands(const mechanics::State& state, double dt) override;
    void begin_attempt() override;
    // Accepted: the tools rest at their targets, a slipped grasp is let go and the wrench
    // of the step goes through the passivity observer. Not: the targets stay for the next
    // step. Either way each tool's output is written.
    void end_step(bool accepted) override;
    // The tools' poses, grasps, proxies, passivity observers, outputs and impulses, and the
    // contacts of the last evaluation used.
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
    const Mat3& last_stiffness(std::size_t index) const { return tools_[index].stiffness; }
    // Tool `index`'s force on the tool at its last evaluation, with the bowel as it was (N).
    Vec3 last_force(std::size_t index) const;

private:
    // A contact of a tool with the bowel, or its grasp, as the last evaluation made it.
    struct Contact {
        static constexpr uint32_t kGrasp = ~uint32_t{0};
        uint32_t sphere = kGrasp;  // the collision sphere touched; kGrasp for the grasp's spring
        double depth = 0.0;        // m
        Vec3 normal = Vec3::UnitZ();  // from the tool to the sphere
        spline::SegmentWeights weights;
        Vec3 force;      // on the bowel, N
        Mat3 stiffness;  // H of the implicit system, N/m
        Mat3 damping;    // C of the implicit system, N s/m
        Vec3 position;   // of the bowel's point at the evaluation, m
        Vec3 velocity;   // of the bowel's point at the evaluation, m/s
        Vec3 arm;        // from the tool's tip to where the force acts on the tool, m
    };
    struct Tool {
        ToolSettings settings;
        ContactParameters contact;  // the law of its contacts (the scene's, with its friction)
        bool removed = false;
        ToolPose current;  // the commanded pose at the start of the step
        ToolPose target;   // and at its end
        bool grasping = false;
        bool slipped = false;                // in the current attempt
        spline::SegmentWeights grasp_point;  // material point of the axis held
        uint32_t grasp_sphere = 0;           // the collision sphere it was when grasped
        // The grasp spring's rest length at the step's start, m: where the held point was
        // when grasped (the spring starts slack), closing at kGraspClosingSpeed to the
        // tool's radius plus the bowel's.
        double grasp_rest = 0.0;
        // The proxy: its tip and velocity after the last evaluation the integrator used,
        // and when that was; at the step's start, for a retry.
        Vec3 proxy = Vec3::Zero(), proxy_velocity = Vec3::Zero();
        double proxy_time = 0.0;
        Vec3 step_proxy = Vec3::Zero(), step_proxy_velocity = Vec3::Zero();
        double step_proxy_time = 0.0;
        double proxy_travel = 0.0;  // m, the farther of its tip's and tail's paths in the attempt
        // The last evaluation: its contacts in contacts_, where the proxy rested, its border
        // body, the tip the torque is about and the stiffness.
        std::size_t first_contact = 0, contact_count = 0;
        uint32_t sphere_contacts = 0;
        Vec3 evaluated_proxy = Vec3::Zero(), evaluated_proxy_velocity = Vec3::Zero();
        double evaluated_time = 0.0;
        std::size_t body = 0;
        bool has_body = false;
        Mat3 stiffness = Mat3::Zero();
        // The attempt: what the bowel received, integrated over time.
        Vec3 impulse = Vec3::Zero(), angular_impulse = Vec3::Zero();
        double duration = 0.0;
        Mat3 used_stiffness = Mat3::Zero();
        uint32_t used_contacts = 0;
        // The attempt's impulse of the bowel's contacts (not the grasp) on the tool: the
        // vector sum and the sum of the magnitudes, N s.
        Vec3 attempt_contact_impulse = Vec3::Zero();
        double attempt_contact_impulse_magnitude = 0.0;
        // Accepted.
        ToolWrench wrench;
        Mat3 accepted_stiffness = Mat3::Zero();
        uint32_t contacts = 0;
        PassivityObserver observer;
        Vec3 contact_impulse = Vec3::Zero();     // N s, ToolOutput's
        double contact_impulse_magnitude = 0.0;  // N s
    };
    // A sphere touching a direct tool, before the bound's scale is known.
    struct Hit {
        std::size_t sphere;
        ContactForce force;  // on the bowel
        Vec3 normal;
        double depth;   // m
        Vec3 velocity;  // of the sphere's centre, m/s
        Vec3 arm;       // from the tip to the contact point on the tool's surface, m
    };
    // A tool's shaft at one instant: its tip and back end, and their velocities.
    struct Segment {
        Vec3 tip, tail;                    // m
        Vec3 tip_velocity, tail_velocity;  // m/s
    };
    Segment segment_at(const Tool& tool, double t) const;
    // What a tool publishes (a tool not removed).
    static void write_output(const Tool& tool, ToolOutput& output);
    double fraction_of_step(double t) const;
    // The grasp spring's rest length at time t of the step, m.
    double grasp_rest(const Tool& tool, double t) const;
    // Grasps the axis point nearest the tip (the proxy's in proxy mode) within reach, if any.
    void grasp(Tool& tool, const mechanics::State& state);
    void evaluate_direct(Tool& tool, const mechanics::State& state, double t, double* force,
                         const mechanics::Linearization* lin);
    void evaluate_proxy(Tool& tool, const mechanics::State& state, double t, double* force,
                        const mechanics::Linearization* lin);
    // Adds a contact (its force, H and C already scaled) to the bowel's forces, to the
    // implicit system with lin (the block scale (axial n n^T + transverse I) along `normal`,
    // and stiffness_times_velocity, H v) and to contacts_.
    void apply(const Contact& contact, const Vec3& normal, double axial, double transverse, double scale,
               const Vec3& stiffness_times_velocity, double* force, const mechanics::Linearization* lin);
    // Collision sphere `sphere`'s contact (`depth` deep; the law's force cf along `normal`,
    // scaled by `scale`; the sphere's velocity; the arm from the tip) made and applied; returns it.
    const Contact& apply_sphere(std::size_t sphere, double depth, const ContactForce& cf, const Vec3& normal,
                                double scale, const Vec3& position, const Vec3& velocity, const Vec3& arm, double* force,
                                const mechanics::Linearization* lin);

    CollisionSpheres& spheres_;  // shared with the other contact effects
    ToolChannels& channels_;
    ContactParameters contact_;
    std::pmr::vector<Tool> tools_;
    std::pmr::vector<Contact> contacts_;             // every tool's, of the last evaluation
    std::pmr::vector<Hit> hits_;                     // a direct tool's, while it is evaluated
    std::pmr::vector<ProxyCandidate> candidates_;    // spheres near a proxy
    ToolProxy proxy_;
    const mechanics::BorderedSystem* border_ = nullptr;  // of the last evaluation, if implicit
    double step_start_ = 0.0;
    double step_dt_ = 0.0;  // 0 between steps
    mechanics::ContactSummary last_;
    ContactLog log_;
};

}  // namespace enteron::collision
