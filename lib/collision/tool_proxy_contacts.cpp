// SPDX-License-Identifier: Apache-2.0
#include "collision/tool_proxy_contacts.h"

#include <algorithm>

#include "mechanics/bordered_system.h"

namespace enteron::collision {

namespace {

// The box around where a proxy may go in one solve: its shaft where it was and where the
// device is, grown by twice the reach (it may slide half round a tube on its way) and its
// blade's half width.
struct SweptBox {
    Vec3 low, high;
    SweptBox(const Vec3& from, const Vec3& to, const Vec3& shaft, double reach, const Vec3& side) {
        const Vec3 width = side.cwiseAbs();
        low = from.cwiseMin(to).cwiseMin(from + shaft).cwiseMin(to + shaft).array() - 2.0 * reach - width.array();
        high = from.cwiseMax(to).cwiseMax(from + shaft).cwiseMax(to + shaft).array() + 2.0 * reach + width.array();
    }
    bool contains(const Vec3& p) const { return !((p.array() < low.array()) || (p.array() > high.array())).any(); }
};

// From the proxy's tip to where contact c's force acts on the tool's surface, m.
Vec3 arm_of(const ProxyContact& c, const ProxyProblem& problem, double radius) {
    Vec3 arm = c.s * problem.shaft + radius * c.normal;
    if (c.w != 0.0) arm += c.w * problem.blade.side;
    return arm;
}

}  // namespace

void ProxyContacts::reserve(std::size_t spheres) {
    candidates_.reserve(spheres);
    proxy_.reserve(spheres);
}

void ProxyContacts::evaluate(ToolState& tool, const ShaftAt& at, double t, double grasp_rest,
                             const mechanics::State& state, const CollisionSpheres& spheres,
                             ToolContacts& contacts) {
    ToolEvaluation& evaluation = tool.evaluation;
    ProxyProblem problem;
    problem.shaft = at.tail - at.tip;
    problem.shaft_velocity = at.tail_velocity - at.tip_velocity;
    problem.blade = {at.side, blade_share(tool.settings)};
    problem.side_velocity = at.side_velocity;
    problem.reach = tool.settings.radius + spheres.radius();
    problem.contact = tool.contact;
    problem.coupling_stiffness = tool.settings.coupling_stiffness;
    problem.coupling_damping = tool.settings.coupling_damping;
    problem.max_force = tool.settings.max_force;
    problem.start = tool.proxy.position;
    problem.start_velocity = tool.proxy.velocity;
    problem.target = at.tip;
    // The coupling's damper takes the tip's velocity over the last two steps. A device that
    // turns back within one tick flips its velocity at once, and b_c (v_x - v_p) flipped with
    // it: a click of up to 2 b_c |v| in one tick (0.16 N at 80 mm/s, docs/haptics.md). The
    // mean of two steps spreads it over two ticks and stays dissipative: against the step's
    // velocity its response e^(-i w dt / 2) cos(w dt / 2) has a real part >= 0.
    problem.target_velocity = 0.5 * (at.tip_velocity + tool.last_tip_velocity);
    problem.dt = std::max(0.0, t - tool.proxy.time);
    // The spheres the proxy may meet on its way from where it was to the device.
    candidates_.clear();
    const SweptBox box(tool.proxy.position, at.tip, problem.shaft, problem.reach, at.side);
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const Sphere& sphere = spheres[i];
        if (!box.contains(sphere.center)) continue;
        candidates_.push_back({i, sphere.center, spline::evaluate(state.v.data(), sphere.weights),
                               spheres.radius() - sphere.radius});
    }
    const bool holding = tool.grasp.holding && !tool.grasp.slipped;
    if (holding) {
        problem.grasp.holding = true;
        problem.grasp.point = spline::evaluate(state.q.data(), tool.grasp.point);
        problem.grasp.velocity = spline::evaluate(state.v.data(), tool.grasp.point);
        problem.grasp.rest = grasp_rest;
        problem.grasp.law = tool.grasp_law;
    }
    ProxyResult result = proxy_.solve(problem, candidates_);
    tool.proxy_work.count(result.iterations, result.evaluations, result.balanced);
    // Holding would take more than max_force: the grasp slips (let go when the step is
    // accepted) and the proxy rests without it.
    if (holding && result.grasp.taut && result.saturated) {
        tool.grasp.slipped = true;
        problem.grasp.holding = false;
        result = proxy_.solve(problem, candidates_);
        tool.proxy_work.count(result.iterations, result.evaluations, result.balanced);
    }
    evaluation.rested = {result.position, result.velocity, t};
    evaluation.stiffness = result.device_stiffness;

    // What the proxy gives the bowel: its contacts' forces, which balance the coupling force.
    const mechanics::Linearization* lin = contacts.linearization();
    Vec3 total = result.grasp.force;
    for (const ProxyContact& c : proxy_.contacts()) total += c.force.force;
    const double magnitude = total.norm();
    const double scale = lin == nullptr && magnitude > tool.settings.max_force ? tool.settings.max_force / magnitude : 1.0;
    evaluation.bounded = result.saturated || scale < 1.0;
    const double h = contacts.h();
    Mat3 block = Mat3::Zero();      // h sum E_i of the border body
    Vec3 predicted = Vec3::Zero();  // sum of the forces less h H v: the g-hats of the border
    const auto add_to_body = [&](const ToolContact& contact, const ContactLinearization& l) {
        block += l.axial * outer(contact.normal) + l.transverse * Mat3::Identity();
        predicted += contact.force - h * (contact.stiffness * contact.velocity);
    };
    for (const ProxyContact& c : proxy_.contacts()) {
        const ProxyCandidate& candidate = candidates_[c.candidate];
        const ToolContact& contact = contacts.add_sphere(
            static_cast<uint32_t>(candidate.sphere), spheres[candidate.sphere].weights, c.depth, c.force, c.normal,
            scale, candidate.center, candidate.velocity, arm_of(c, problem, tool.settings.radius));
        add_to_body(contact, contact_linearization(c.force, h));
    }
    evaluation.sphere_contacts = static_cast<uint32_t>(proxy_.contacts().size());
    if (problem.grasp.holding && result.grasp.taut) {
        const ToolContact& contact = contacts.add_grasp(result.grasp, problem.grasp.law, tool.grasp.point, scale,
                                                        problem.grasp.point, problem.grasp.velocity);
        add_to_body(contact, grasp_linearization(result.grasp, problem.grasp.law, h));
    }
    if (lin != nullptr && lin->border != nullptr) {
        // The proxy's balance at the end of the substep (above).
        evaluation.body = lin->border->add_body(block, h * (result.coupling_force - predicted));
        evaluation.has_body = true;
        for (std::size_t k = evaluation.first_contact; k < contacts.size(); ++k) {
            const ToolContact& contact = contacts[k];
            lin->border->add_coupling(evaluation.body, contact.weights, h * (h * contact.stiffness + contact.damping));
        }
    }
}

}  // namespace enteron::collision
