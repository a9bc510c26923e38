// The tool entry points of the C API: surgical instruments that push and grasp the bowel.
// ent_tool_add is a driving call; the commands (pose, grasp, release) go through each
// tool's wait-free mailbox and the outputs come from the published snapshot, so both work
// from any thread while another steps.
#include <cstring>
#include <string>

#include "capi/call_guard.h"
#include "capi/driving_call.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "collision/tool.h"
#include "scene/plausible_ranges.h"
#include "scene/validate.h"

namespace {

using enteron::Error;
using enteron::ErrorCode;
using enteron::capi::SceneHandle;
using enteron::capi::guarded;
using enteron::capi::live_handle;
using enteron::capi::require;
using enteron::collision::ToolMailbox;

[[noreturn]] void unknown_tool(int32_t tool, std::size_t count) {
    throw Error(ErrorCode::not_found,
                "tool " + std::to_string(tool) + " does not exist (the scene has " + std::to_string(count) + " tools)");
}

// The mailbox of a tool id, or NOT_FOUND naming it. Any thread.
ToolMailbox& mailbox_of(SceneHandle& handle, int32_t tool) {
    enteron::collision::ToolChannels& channels = handle.scene->tool_channels();
    ToolMailbox* mailbox = tool >= 0 ? channels.mailbox(static_cast<std::size_t>(tool)) : nullptr;
    if (mailbox == nullptr) unknown_tool(tool, channels.size());
    return *mailbox;
}

// The published output of a tool id, copied from the latest snapshot, with that
// snapshot's time and step count. Any thread.
struct PublishedTool {
    enteron::collision::ToolOutput output;
    double time_s;
    uint64_t steps;
};
PublishedTool published_tool(const SceneHandle& handle, int32_t tool) {
    const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
    if (tool < 0 || static_cast<std::size_t>(tool) >= snapshot->tools.size())
        unknown_tool(tool, snapshot->tools.size());
    return {snapshot->tools[static_cast<std::size_t>(tool)], snapshot->stats.time, snapshot->stats.steps};
}

}  // namespace

extern "C" {

ENT_API ent_status ent_tool_desc_init(ent_tool_desc* desc, uint32_t struct_size) {
    return guarded([&] {
        require(desc, "desc");
        enteron::capi::check_struct_size(struct_size, {sizeof(ent_tool_desc)}, "ent_tool_desc");
        const enteron::collision::ToolConfig tool;
        ent_tool_desc defaults;
        std::memset(&defaults, 0, sizeof defaults);
        defaults.struct_size = struct_size;
        defaults.radius_m = tool.settings.radius;
        defaults.length_m = tool.settings.length;
        defaults.max_force_N = tool.settings.max_force;
        defaults.grasp_margin_m = tool.settings.grasp_margin;
        defaults.grasp_stiffness_N_per_m = tool.settings.grasp_stiffness;
        defaults.grasp_damping_N_s_per_m = tool.settings.grasp_damping;
        for (int c = 0; c < 3; ++c) defaults.position_m[c] = tool.pose.position[c];
        for (int c = 0; c < 4; ++c) defaults.orientation_wxyz[c] = tool.pose.orientation[c];
        std::memcpy(desc, &defaults, struct_size);
    });
}

ENT_API ent_status ent_tool_add(ent_scene* scene, const ent_tool_desc* desc, int32_t* out_tool) {
    return guarded([&] {
        SceneHandle& handle = live_handle(scene);
        require(desc, "desc");
        enteron::capi::check_struct_size(desc->struct_size, {sizeof(ent_tool_desc)}, "ent_tool_desc");
        const enteron::capi::DrivingCall driving(handle, "ent_tool_add");
        enteron::collision::ToolConfig tool;
        tool.settings.radius = desc->radius_m;
        tool.settings.length = desc->length_m;
        tool.settings.max_force = desc->max_force_N;
        tool.settings.grasp_margin = desc->grasp_margin_m;
        tool.settings.grasp_stiffness = desc->grasp_stiffness_N_per_m;
        tool.settings.grasp_damping = desc->grasp_damping_N_s_per_m;
        for (int c = 0; c < 3; ++c) tool.pose.position[c] = desc->position_m[c];
        for (int c = 0; c < 4; ++c) tool.pose.orientation[c] = desc->orientation_wxyz[c];
        const enteron::scene::FieldNames& names = enteron::scene::c_field_names();
        tool = enteron::scene::validate_tool(tool, "", names);
        enteron::scene::warn_implausible(tool.settings, "", names, handle.logger);
        const std::size_t index = handle.scene->add_tool(tool);
        if (out_tool != nullptr) *out_tool = static_cast<int32_t>(index);
    });
}

ENT_API ent_status ent_tool_set_pose(ent_scene* scene, int32_t tool, const double position_m[3],
                                     const double orientation_wxyz[4]) {
    return guarded([&] {
        SceneHandle& handle = live_handle(scene);
        require(position_m, "position_m");
        require(orientation_wxyz, "orientation_wxyz");
        ToolMailbox& mailbox = mailbox_of(handle, tool);
        enteron::collision::ToolPose pose;
        for (int c = 0; c < 3; ++c) pose.position[c] = position_m[c];
        for (int c = 0; c < 4; ++c) pose.orientation[c] = orientation_wxyz[c];
        mailbox.post_pose(enteron::scene::validate_tool_pose(pose, "", enteron::scene::c_field_names()));
    });
}

ENT_API ent_status ent_tool_grasp(ent_scene* scene, int32_t tool) {
    return guarded([&] { mailbox_of(live_handle(scene), tool).post_grasp(ToolMailbox::Grasp::grasp); });
}

ENT_API ent_status ent_tool_release(ent_scene* scene, int32_t tool) {
    return guarded([&] { mailbox_of(live_handle(scene), tool).post_grasp(ToolMailbox::Grasp::release); });
}

ENT_API ent_status ent_tool_wrench(const ent_scene* scene, int32_t tool, double force_N[3], double torque_Nm[3]) {
    return guarded([&] {
        const SceneHandle& handle = live_handle(scene);
        require(force_N, "force_N");
        require(torque_Nm, "torque_Nm");
        const enteron::collision::ToolWrench wrench = published_tool(handle, tool).output.wrench;
        for (int c = 0; c < 3; ++c) force_N[c] = wrench.force[c], torque_Nm[c] = wrench.torque[c];
    });
}

ENT_API ent_status ent_tool_state(const ent_scene* scene, int32_t tool, int32_t* out_grasping) {
    return guarded([&] {
        const SceneHandle& handle = live_handle(scene);
        require(out_grasping, "out_grasping");
        *out_grasping = published_tool(handle, tool).output.grasping ? 1 : 0;
    });
}

ENT_API ent_status ent_tool_read_feedback(const ent_scene* scene, int32_t tool, ent_tool_feedback* out) {
    return guarded([&] {
        const SceneHandle& handle = live_handle(scene);
        require(out, "out");
        // The sizes of ent_tool_feedback in released headers: only the current one so far.
        enteron::capi::check_struct_size(out->struct_size, {sizeof(ent_tool_feedback)}, "ent_tool_feedback");
        const PublishedTool published = published_tool(handle, tool);
        const enteron::collision::ToolOutput& output = published.output;
        ent_tool_feedback full{};
        full.struct_size = out->struct_size;
        for (int c = 0; c < 3; ++c) {
            full.force_N[c] = output.wrench.force[c];
            full.torque_Nm[c] = output.wrench.torque[c];
        }
        full.grasping = output.grasping ? 1 : 0;
        full.contacts = output.contacts;
        full.time_s = published.time_s;
        full.steps = published.steps;
        std::memcpy(out, &full, out->struct_size);
    });
}

}  // extern "C"
