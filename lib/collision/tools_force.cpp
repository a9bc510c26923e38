// SPDX-License-Identifier: Apache-2.0
#include "collision/tools_force.h"

#include <algorithm>
#include <cmath>

#include "collision/grasp_aim.h"
#include "collision/tool_grasp.h"
#include "collision/tool_outputs.h"
#include "collision/tool_shaft.h"

namespace enteron::collision {

ToolsForce::ToolsForce(CollisionSpheres& spheres, const ContactParameters& contact, const mechanics::State& initial,
                       ToolChannels& channels, std::pmr::memory_resource* memory)
    : spheres_(spheres),
      channels_(channels),
      contact_(contact),
      tools_(memory),
      contacts_(memory),
      direct_(memory),
      proxy_(memory),
      log_(ContactKind::tool, kLoggedContactsPerSphere * spheres.size(), memory) {
    direct_.reserve(spheres_.size());
    proxy_.reserve(spheres_.size());
    spheres_.update(initial.q.data());
}

std::size_t ToolsForce::add_tool(const ToolConfig& config) {
    ToolState tool;
    tool.settings = config.settings;
    tool.contact = contact_;
    if (tool.settings.friction >= 0.0) tool.contact.friction = tool.settings.friction;
    tool.grasp_law = {tool.settings.grasp_stiffness, tool.settings.grasp_damping};
    if (tool.settings.mode == ToolMode::proxy)
        tool.contact.stiffness = proxy_contact_stiffness(contact_.stiffness, tool.settings.max_force, spheres_.radius());
    tool.current = tool.target = config.pose;
    tool.proxy.position = config.pose.position;
    tool.proxy_at_start = tool.proxy;
    tool.grasp.rest = tool.settings.radius + spheres_.radius();
    // Nothing changes if an allocation fails: every reservation comes first. Each tool may
    // touch every sphere and hold one point.
    tools_.reserve(tools_.size() + 1);
    contacts_.reserve((tools_.size() + 1) * (spheres_.size() + 1));
    channels_.add(config);
    tools_.push_back(tool);
    return tools_.size() - 1;
}

void ToolsForce::remove_tool(std::size_t index) {
    ToolState& tool = tools_[index];
    tool.removed = true;
    tool.grasp.holding = false;
    tool.evaluation.contact_count = tool.evaluation.sphere_contacts = tool.accepted.contacts = 0;
    tool.accepted.wrench = ToolWrench{};
    tool.evaluation.stiffness = tool.accepted.stiffness = Mat3::Zero();
    ToolOutput& output = channels_.outputs()[index];
    output = ToolOutput{};
    output.removed = true;
    channels_.mailbox(index)->retire();
}

// Commands.

bool ToolsForce::take_commands(const mechanics::State& state, double dt) {
    bool grasp_changed = false;
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        ToolState& tool = tools_[i];
        if (tool.removed) continue;
        ToolMailbox& mailbox = *channels_.mailbox(i);
        mailbox.take_pose(tool.target);
        switch (mailbox.take_grasp()) {
            case ToolMailbox::Grasp::none: break;
            case ToolMailbox::Grasp::grasp: take_grasp(tool, state); grasp_changed = true; break;
            case ToolMailbox::Grasp::release: tool.grasp.holding = false; grasp_changed = true; break;
        }
        tool.proxy_at_start = tool.proxy;
        tool.proxy_work.step_iterations = tool.proxy_work.step_evaluations = 0;
    }
    step_ = {state.time, dt};
    return grasp_changed;
}

void ToolsForce::take_grasp(ToolState& tool, const mechanics::State& state) {
    spheres_.update(state.q.data());
    // Where the tool rests: the proxy's tip (the commanded tip in direct mode), its jaws
    // turned as commanded.
    Jaws jaws;
    jaws.tip = tool.settings.mode == ToolMode::proxy ? tool.proxy.position : tool.current.position;
    jaws.axis = quaternion_z_axis(tool.current.orientation);
    jaws.across = quaternion_x_axis(tool.current.orientation);
    jaws.length = std::min(tool.settings.jaw_length, tool.settings.length);
    jaws.half_opening = 0.5 * tool.settings.jaw_opening;
    // Each sphere at its own radius (the profile's at its place), so a thin stretch is
    // reached at its own surface, not at the largest radius'.
    GraspAim aim(jaws, tool.settings.radius, tool.settings.grasp_margin);
    for (std::size_t i = 0; i < spheres_.size(); ++i) aim.offer(i, spheres_[i].center, spheres_[i].radius);
    if (aim.found()) {
        tool.grasp.point = spheres_[aim.picked()].weights;
        tool.grasp.sphere = static_cast<uint32_t>(aim.picked());
        tool.grasp.holding = true;
        // The spring starts slack wherever the held point is (no jolt), then closes.
        tool.grasp.rest = std::max(grasp_surface(tool), std::sqrt(aim.picked_tip_distance2()));
    }
}

double ToolsForce::grasp_surface(const ToolState& tool) const {
    return tool.settings.radius + spheres_[tool.grasp.sphere].radius;
}

double ToolsForce::grasp_rest_at(const ToolState& tool, double t) const {
    return grasp_rest(tool.grasp.rest, grasp_surface(tool), step_.elapsed(t));
}

// The attempts.

void ToolsForce::begin_attempt() {
    for (ToolState& tool : tools_) {
        tool.grasp.slipped = false;
        tool.proxy = tool.proxy_at_start;
        tool.attempt = AttemptSums{};
    }
}

void ToolsForce::evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) {
    spheres_.update(state.q.data());
    contacts_.begin(force, lin);
    border_ = lin != nullptr ? lin->border : nullptr;
    // The implicit step solves for the end of the substep: meet the tool where it is then.
    const double t = state.time + (lin != nullptr ? lin->h : 0.0);
    for (ToolState& tool : tools_) {
        ToolEvaluation& evaluation = tool.evaluation;
        evaluation.first_contact = contacts_.size();
        evaluation.contact_count = 0;
        evaluation.sphere_contacts = 0;
        evaluation.has_body = false;
        if (tool.removed) continue;
        const ShaftAt shaft = commanded_shaft(tool.current, tool.target, tool.settings.length, step_, t,
                                              0.5 * tool.settings.blade_width);
        const double rest = grasp_rest_at(tool, t);
        if (tool.settings.mode == ToolMode::proxy)
            proxy_.evaluate(tool, shaft, t, rest, state, spheres_, contacts_);
        else
            direct_.evaluate(tool, shaft, t, rest, state, spheres_, contacts_);
        evaluation.contact_count = contacts_.size() - evaluation.first_contact;
    }
    last_ = contacts_.summary();
}

Vec3 ToolsForce::last_force(std::size_t index) const {
    const ToolEvaluation& evaluation = tools_[index].evaluation;
    Vec3 total = Vec3::Zero();
    for (std::size_t k = evaluation.first_contact; k < evaluation.first_contact + evaluation.contact_count; ++k)
        total += contacts_[k].force;
    return -total;
}

void ToolsForce::evaluation_used(double duration, const mechanics::State* after) {
    log_.clear();
    for (std::size_t index = 0; index < tools_.size(); ++index) {
        ToolState& tool = tools_[index];
        if (tool.removed) continue;
        const ToolEvaluation& evaluation = tool.evaluation;
        // The proxy's motion over the substep, as the implicit step solved it with the bowel.
        const Vec3 proxy_move = after != nullptr && evaluation.has_body
                                    ? Vec3(duration * border_->solution(evaluation.body))
                                    : Vec3::Zero();
        add_evaluation_received(tool, static_cast<uint32_t>(index), contacts_, duration, after, proxy_move, log_);
        // The proxy is where this evaluation put it (and moved with the bowel since).
        const Vec3 before = tool.proxy.position;
        tool.proxy.position = evaluation.rested.position + proxy_move;
        tool.proxy.velocity =
            evaluation.rested.velocity + (duration > 0.0 ? Vec3(proxy_move / duration) : Vec3::Zero());
        tool.proxy.time = evaluation.rested.time;
        tool.attempt.proxy_travel += (tool.proxy.position - before).norm();
    }
}

void ToolsForce::end_step(bool accepted) {
    std::pmr::vector<ToolOutput>& outputs = channels_.outputs();
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        ToolState& tool = tools_[i];
        if (tool.removed) continue;
        if (accepted) {
            if (tool.grasp.slipped) tool.grasp.holding = false;
            accept_outputs(tool);
            tool.grasp.rest = grasp_rest_at(tool, step_.start + step_.dt);
            if (step_.dt > 0.0) tool.last_tip_velocity = (tool.target.position - tool.current.position) / step_.dt;
            tool.current = tool.target;
        } else {
            tool.proxy = tool.proxy_at_start;
        }
        tool.grasp.slipped = false;
        write_output(tool, outputs[i]);
    }
    step_.dt = 0.0;
}

// What the guard and the explicit integrators ask.

double ToolsForce::potential_energy(const mechanics::State& state) const {
    spheres_.update(state.q.data());
    const double r = spheres_.radius();
    double energy = 0.0;
    for (const ToolState& tool : tools_) {
        if (tool.removed) continue;
        // The capsule the bowel meets: the proxy where it rests now (with the commanded
        // orientation), or the commanded pose itself.
        const ShaftAt at = commanded_shaft(tool.current, tool.target, tool.settings.length, step_, state.time,
                                           0.5 * tool.settings.blade_width);
        const bool proxy = tool.settings.mode == ToolMode::proxy;
        const Vec3 tip = proxy ? tool.proxy.position : at.tip;
        const Shaft shaft(tip, tip + (at.tail - at.tip), tool.settings.radius + r, {at.side, blade_share(tool.settings)});
        double stored = 0.0, total_magnitude = 0.0;
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            ShaftPoint where;
            double dist2;
            Vec3 d;
            if (!shaft.touches(spheres_[i].center, &where, &d, &dist2)) continue;
            // Each sphere at its own radius, as the contacts take it (the shaft reaches as
            // far as the largest).
            const double depth = shaft.reach - std::sqrt(dist2) - (r - spheres_[i].radius);
            if (!(depth > 0.0)) continue;
            stored += 0.5 * tool.contact.stiffness * depth * depth;
            total_magnitude += tool.contact.stiffness * depth;
        }
        // The spring energy as far as the bound lets the contacts push (the direct law's
        // scale); the proxy's contacts never push harder than max_force in all.
        energy += !proxy && total_magnitude > tool.settings.max_force
                      ? stored * tool.settings.max_force / total_magnitude
                      : stored;
        // A grasp that slipped in this step holds no spring at its end: the guard must not
        // count the energy of the spring it let go of, however far the jump stretched it.
        if (tool.grasp.holding && !tool.grasp.slipped)
            energy += grasp_energy(tool.grasp_law, grasp_rest_at(tool, state.time), tip,
                                   spline::evaluate(state.q.data(), tool.grasp.point));
    }
    return energy;
}

void ToolsForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    double stiffness = 0.0;
    for (const ToolState& tool : tools_)
        if (!tool.removed) stiffness += tool.contact.stiffness + tool.grasp_law.stiffness;
    spheres_.add_weight_products(stiffness, bound);
}

void ToolsForce::add_damping_bound(numerics::ScalarBandMatrix& bound) const {
    double damping = 0.0;
    for (const ToolState& tool : tools_)
        if (!tool.removed)
            damping += tool.contact.damping + friction_damping_bound(tool.contact, spheres_.radius()) +
                       tool.grasp_law.damping;
    spheres_.add_weight_products(damping, bound);
}

void ToolsForce::add_contacts(mechanics::ContactSummary& summary) const {
    summary.count += last_.count;
    summary.max_penetration = std::max(summary.max_penetration, last_.max_penetration);
}

void ToolsForce::add_work(mechanics::StepWork& work) const {
    for (const ToolState& tool : tools_) {
        work.proxy_iterations = std::max(work.proxy_iterations, tool.proxy_work.step_iterations);
        work.proxy_evaluations += tool.proxy_work.step_evaluations;
        work.proxy_unbalanced += tool.proxy_work.unbalanced_solves;
    }
}

std::size_t ToolsForce::border_bodies() const {
    std::size_t bodies = 0;
    for (const ToolState& tool : tools_) bodies += !tool.removed && tool.settings.mode == ToolMode::proxy;
    return bodies;
}

double ToolsForce::external_work_bound() const {
    if (!(step_.dt > 0.0)) return 0.0;
    double work = 0.0;
    for (const ToolState& tool : tools_) {
        if (tool.removed) continue;
        // Every point of the shaft moves at most as far as its ends (twice that for the
        // arc of a turn and the contact damping's share). A proxy goes its own way: the
        // length of its tip's path, and how far the turn of the shaft moved its back end.
        const ShaftTravel travel = commanded_travel(tool.current, tool.target, tool.settings.length);
        const double move = tool.settings.mode == ToolMode::proxy ? tool.attempt.proxy_travel + travel.turn
                                                                   : std::max(travel.tip, travel.tail);
        work += 2.0 * tool.settings.max_force * move;
    }
    return work;
}

}  // namespace enteron::collision
