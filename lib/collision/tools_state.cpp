// SPDX-License-Identifier: Apache-2.0
// Save and restore of the tools effect (tools_force.h, docs/scoring-and-state.md). Between
// steps a tool's state is its poses, grasp, proxy (where the last evaluation used left it),
// accepted outputs, passivity observer and impulses; the rest is made again by the next step
// (the attempt's sums, the evaluation's contacts).
#include <cmath>
#include <string>

#include "base/state_io.h"
#include "collision/tool_outputs.h"
#include "collision/tools_force.h"

namespace enteron::collision {

namespace {

void save_pose(StateWriter& out, const ToolPose& pose) {
    out.f64s(pose.position.data(), 3);
    out.f64s(pose.orientation.data(), 4);
}

ToolPose restore_pose(StateReader& in, const char* what) {
    ToolPose pose;
    in.f64s(what, 3, pose.position.data());
    in.f64s(what, 4, pose.orientation.data());
    if (!(std::fabs(Eigen::Map<const Vec4>(pose.orientation.data()).norm() - 1.0) <= 1e-9))
        in.fail(std::string(what) + ": the orientation is not a unit quaternion");
    return pose;
}

void save_mat3(StateWriter& out, const Mat3& m) { out.f64s(m.data(), 9); }

}  // namespace

void ToolsForce::save_state(StateWriter& out) const {
    out.begin_section("tools", 4);
    out.u32(static_cast<uint32_t>(tools_.size()));
    for (const ToolState& tool : tools_) {
        out.u8(tool.removed ? 1 : 0);
        save_pose(out, tool.current);
        save_pose(out, tool.target);
        out.u8(tool.grasp.holding ? 1 : 0);
        out.u32(static_cast<uint32_t>(tool.grasp.point.first));
        out.f64s(tool.grasp.point.w.data(), 4);
        out.u32(tool.grasp.sphere);
        out.f64(tool.grasp.rest);
        out.f64s(tool.proxy.position.data(), 3);
        out.f64s(tool.proxy.velocity.data(), 3);
        out.f64(tool.proxy.time);
        save_mat3(out, tool.evaluation.stiffness);
        out.f64s(tool.accepted.wrench.force.data(), 3);
        out.f64s(tool.accepted.wrench.torque.data(), 3);
        save_mat3(out, tool.accepted.stiffness);
        out.u32(tool.accepted.contacts);
        tool.accepted.observer.save_state(out);
        out.f64s(tool.accepted.contact_impulse.data(), 3);
        out.f64(tool.accepted.contact_impulse_magnitude);
        out.u8(tool.accepted.saturated ? 1 : 0);
        out.f64s(tool.last_tip_velocity.data(), 3);
    }
    out.u32(last_.count);
    out.f64(last_.max_penetration);
    log_.save_state(out);
    out.end_section();
}

void ToolsForce::restore_state(StateReader& in) {
    // Version 1 (before the proxy) cannot give a proxy's state: refused as too old.
    const uint32_t version = in.begin_section("tools", 4);
    if (version < 2) in.fail("saved before tools had proxies (version 1); save it again");
    if (in.u32("tools") != tools_.size()) in.fail("saved with another number of tools");
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        ToolState& tool = tools_[i];
        ToolState saved = tool;
        if (in.flag("tool removed") != tool.removed)
            in.fail("tool " + std::to_string(i) + (tool.removed ? " was removed from this scene but not from the saved one"
                                                                 : " was removed from the saved scene but not from this one"));
        saved.current = restore_pose(in, "tool pose");
        saved.target = restore_pose(in, "tool target pose");
        saved.grasp.holding = in.flag("grasping");
        saved.grasp.point.first = in.index("first control point grasped", spheres_.control_points() - 3);
        in.f64s("grasp weights", 4, saved.grasp.point.w.data());
        saved.grasp.sphere = in.index("sphere grasped", spheres_.size());
        // Version 2 held the point on the tool's surface from the start (the held sphere's).
        const double surface = tool.settings.radius + spheres_[saved.grasp.sphere].radius;
        saved.grasp.rest = version >= 3 ? in.f64("grasp rest length") : surface;
        if (!(saved.grasp.rest >= surface) || !std::isfinite(saved.grasp.rest))
            in.fail("grasp rest length shorter than the tool's radius plus the bowel's, or not finite");
        in.f64s("proxy position", 3, saved.proxy.position.data());
        in.f64s("proxy velocity", 3, saved.proxy.velocity.data());
        saved.proxy.time = in.f64("proxy time");
        in.f64s("tool stiffness", 9, saved.evaluation.stiffness.data());
        in.f64s("tool force", 3, saved.accepted.wrench.force.data());
        in.f64s("tool torque", 3, saved.accepted.wrench.torque.data());
        in.f64s("published tool stiffness", 9, saved.accepted.stiffness.data());
        saved.accepted.contacts = in.count("tool contacts", spheres_.size());
        PassivityObserver::restore_state(in, saved.accepted.observer);
        in.f64s("contact impulse", 3, saved.accepted.contact_impulse.data());
        saved.accepted.contact_impulse_magnitude = in.f64("contact impulse magnitude");
        // Version 3 and before did not say whether max_force bounded the last step, nor how
        // fast the tool moved in it (taken as still).
        saved.accepted.saturated = version >= 4 && in.flag("force saturated");
        saved.last_tip_velocity = Vec3::Zero();
        if (version >= 4) in.f64s("tip velocity", 3, saved.last_tip_velocity.data());
        saved.proxy_at_start = saved.proxy;
        saved.grasp.slipped = false;
        if (!in.checking()) tool = saved;
    }
    const uint32_t contacts = in.count("contacts", spheres_.size() * (tools_.size() + 1));
    const double max_penetration = in.f64("deepest contact");
    log_.restore_state(in, spheres_.size(), tools_.size());
    in.end_section();
    if (in.checking()) return;
    last_ = {contacts, max_penetration};
    for (std::size_t i = 0; i < tools_.size(); ++i)
        if (!tools_[i].removed) write_output(tools_[i], channels_.outputs()[i]);
}

}  // namespace enteron::collision
