// SPDX-License-Identifier: Apache-2.0
#include "collision/tool_outputs.h"

namespace enteron::collision {

void add_evaluation_received(ToolState& tool, uint32_t index, const ToolContacts& contacts, double duration,
                             const mechanics::State* after, const Vec3& proxy_move, ContactLog& log) {
    const ToolEvaluation& evaluation = tool.evaluation;
    Vec3 received = Vec3::Zero(), torque = Vec3::Zero(), touched = Vec3::Zero();
    // The tip the arms start from, where this evaluation leaves it.
    const Vec3 tip = evaluation.rested.position + proxy_move;
    for (std::size_t k = evaluation.first_contact; k < evaluation.first_contact + evaluation.contact_count; ++k) {
        const ToolContact& contact = contacts[k];
        Vec3 force = contact.force;
        if (after != nullptr) {
            // The linearised force at the end of the substep: F - H (dq - dp) - C (dv - dp / h).
            const Vec3 v = spline::evaluate(after->v.data(), contact.weights);
            const Vec3 moved = spline::evaluate(after->q.data(), contact.weights) - contact.position - proxy_move;
            const Vec3 sped = v - contact.velocity - proxy_move / duration;
            force -= contact.stiffness * moved + contact.damping * sped;
        }
        received += force;
        torque += contact.arm.cross(-force);
        if (contact.sphere == ToolContact::kGrasp) continue;
        touched += force;
        log.add(contact.sphere, index, contact.depth, tip + contact.arm, contact.normal, force);
    }
    AttemptSums& attempt = tool.attempt;
    attempt.contact_impulse -= duration * touched;
    attempt.contact_impulse_magnitude += duration * touched.norm();
    attempt.impulse += duration * received;
    attempt.angular_impulse += duration * torque;
    attempt.duration += duration;
    attempt.stiffness = evaluation.stiffness;
    attempt.contacts = evaluation.sphere_contacts;
    attempt.saturated = attempt.saturated || evaluation.bounded;
}

void accept_outputs(ToolState& tool) {
    const AttemptSums& attempt = tool.attempt;
    AcceptedOutputs& accepted = tool.accepted;
    // Minus what the bowel received over the step, then the port's passivity.
    ToolWrench received;
    if (attempt.duration > 0.0) {
        received.force = -attempt.impulse / attempt.duration;
        received.torque = attempt.angular_impulse / attempt.duration;
    }
    // A device's safety: never more than max_force. Only where the proxy is not solved with
    // the bowel (clamped ends, bdf2's second-order substeps) can minus what the bowel received
    // exceed it (docs/haptics.md "The wrench"). Clipped before the observer, so that its
    // balance counts the work of the force rendered.
    const double magnitude = received.force.norm();
    if (magnitude > tool.settings.max_force) received.force *= tool.settings.max_force / magnitude;
    accepted.saturated = attempt.saturated || magnitude > tool.settings.max_force;
    const Vec3 displacement = tool.target.position - tool.current.position;
    const Vec3 rotation = rotation_between(tool.current.orientation, tool.target.orientation);
    accepted.wrench = accepted.observer.observe(received, displacement, rotation, tool.settings.max_force,
                                                tool.settings.passivity_limiter);
    accepted.stiffness = attempt.stiffness;
    accepted.contacts = attempt.contacts;
    accepted.contact_impulse += attempt.contact_impulse;
    accepted.contact_impulse_magnitude += attempt.contact_impulse_magnitude;
}

void write_output(const ToolState& tool, ToolOutput& output) {
    output.wrench = tool.accepted.wrench;
    output.grasping = tool.grasp.holding;
    output.contacts = tool.accepted.contacts;
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(output.stiffness.data()) = tool.accepted.stiffness;
    output.commanded = tool.current;
    output.proxy.position = tool.proxy.position;
    output.proxy.orientation = tool.current.orientation;
    output.stats = tool.accepted.observer.stats();
    output.grasp_sphere = tool.grasp.sphere;
    output.contact_impulse = tool.accepted.contact_impulse;
    output.contact_impulse_magnitude = tool.accepted.contact_impulse_magnitude;
    output.saturated = tool.accepted.saturated;
}

}  // namespace enteron::collision
