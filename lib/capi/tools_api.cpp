// SPDX-License-Identifier: Apache-2.0
// The tool entry points of the C API: surgical instruments that push and grasp the bowel.
// ent_tool_add is a driving call; the commands (pose, grasp, release) go through each
// tool's wait-free mailbox and the outputs come from the published snapshot, so both work
// from any thread while another steps.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <string>

#include "capi/call_guard.h"
#include "capi/desc_fields.h"
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
using enteron::capi::SceneCall;
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
    if (mailbox->retired()) throw Error(ErrorCode::not_found, "tool " + std::to_string(tool) + " was removed");
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

// The sizes of ent_tool_desc and ent_tool_feedback in released headers: before the fields
// of the tool's proxy and stiffness, (the desc) before the jaws, (the feedback) before
// saturated, and now.
constexpr std::size_t kToolDescFirstSize = offsetof(ent_tool_desc, mode);
constexpr std::size_t kToolDescProxySize = offsetof(ent_tool_desc, jaw_length_m);
void check_tool_desc_size(uint32_t struct_size) {
    enteron::capi::check_struct_size(struct_size, {kToolDescFirstSize, kToolDescProxySize, sizeof(ent_tool_desc)},
                                     "ent_tool_desc");
}

// ent_tool_desc's fields, each the row of the tool's table with its name
// (scene/scene_table.cpp); struct_size aside, all of them.
#define TOOL_FIELD(field) ENTERON_DESC_FIELD(ent_tool_desc, field)
const enteron::capi::DescField<ent_tool_desc> kToolDescFields[] = {
    TOOL_FIELD(radius_m), TOOL_FIELD(length_m), TOOL_FIELD(max_force_N), TOOL_FIELD(grasp_margin_m),
    TOOL_FIELD(grasp_stiffness_N_per_m), TOOL_FIELD(grasp_damping_N_s_per_m), TOOL_FIELD(position_m),
    TOOL_FIELD(orientation_wxyz), TOOL_FIELD(mode), TOOL_FIELD(passivity_limiter),
    TOOL_FIELD(coupling_stiffness_N_per_m), TOOL_FIELD(coupling_damping_N_s_per_m), TOOL_FIELD(friction),
    TOOL_FIELD(jaw_length_m), TOOL_FIELD(jaw_opening_m), TOOL_FIELD(blade_width_m), TOOL_FIELD(blade_length_m),
};
#undef TOOL_FIELD

const enteron::capi::DescBinding<ent_tool_desc>& tool_desc_fields() {
    static const enteron::capi::DescBinding<ent_tool_desc> binding(enteron::scene::tool_block(), kToolDescFields);
    return binding;
}

// A tool as a whole current ent_tool_desc.
ent_tool_desc desc_of(const enteron::collision::ToolConfig& tool) {
    ent_tool_desc desc;
    std::memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc;
    tool_desc_fields().write(&tool, desc);
    return desc;
}
constexpr std::size_t kToolFeedbackFirstSize = offsetof(ent_tool_feedback, stiffness_N_per_m);
constexpr std::size_t kToolFeedbackProxySize = offsetof(ent_tool_feedback, saturated);

// The published output of a tool that exists and is not removed.
PublishedTool present_tool(const SceneHandle& handle, int32_t tool) {
    PublishedTool published = published_tool(handle, tool);
    if (published.output.removed) throw Error(ErrorCode::not_found, "tool " + std::to_string(tool) + " was removed");
    return published;
}

}  // namespace

extern "C" {

ENT_API ent_status ent_tool_desc_init(ent_tool_desc* desc, uint32_t struct_size) {
    return guarded([&] {
        require(desc, "desc");
        check_tool_desc_size(struct_size);
        ent_tool_desc defaults = desc_of(enteron::collision::ToolConfig{});
        defaults.struct_size = struct_size;
        std::memcpy(desc, &defaults, struct_size);
    });
}

ENT_API ent_status ent_tool_read_desc(const ent_scene* scene, int32_t tool, ent_tool_desc* out) {
    return guarded([&] {
        const enteron::capi::SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out, "out");
        check_tool_desc_size(out->struct_size);
        const enteron::collision::ToolChannels& channels = handle.scene->tool_channels();
        const enteron::collision::ToolConfig* added = tool >= 0 ? channels.added(static_cast<std::size_t>(tool)) : nullptr;
        if (added == nullptr) unknown_tool(tool, channels.size());
        if (channels.mailbox(static_cast<std::size_t>(tool))->retired())
            throw Error(ErrorCode::not_found, "tool " + std::to_string(tool) + " was removed");
        ent_tool_desc desc = desc_of(*added);
        desc.struct_size = out->struct_size;
        // An older caller's struct ends at struct_size: write nothing past it.
        std::memcpy(out, &desc, out->struct_size);
    });
}

ENT_API ent_status ent_tool_add(ent_scene* scene, const ent_tool_desc* desc, int32_t* out_tool) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        require(desc, "desc");
        check_tool_desc_size(desc->struct_size);
        const enteron::capi::DrivingCall driving(handle, "ent_tool_add");
        // An older, smaller desc: its missing fields take their defaults.
        ent_tool_desc full;
        ent_tool_desc_default(&full);
        std::memcpy(&full, desc, desc->struct_size);
        desc = &full;
        enteron::collision::ToolConfig tool;
        tool_desc_fields().read(*desc, &tool);
        const enteron::scene::FieldNames& names = enteron::scene::c_field_names();
        tool = enteron::scene::validate_tool(tool, "", names);
        enteron::scene::warn_implausible(tool, "", names, handle.logger);
        const std::size_t index = handle.scene->add_tool(tool);
        if (out_tool != nullptr) *out_tool = static_cast<int32_t>(index);
    });
}

ENT_API ent_status ent_tool_set_pose(ent_scene* scene, int32_t tool, const double position_m[3],
                                     const double orientation_wxyz[4]) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
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
    return guarded([&] {
        const SceneCall call(scene);
        mailbox_of(call.handle(), tool).post_grasp(ToolMailbox::Grasp::grasp);
    });
}

ENT_API ent_status ent_tool_release(ent_scene* scene, int32_t tool) {
    return guarded([&] {
        const SceneCall call(scene);
        mailbox_of(call.handle(), tool).post_grasp(ToolMailbox::Grasp::release);
    });
}

ENT_API ent_status ent_tool_wrench(const ent_scene* scene, int32_t tool, double force_N[3], double torque_Nm[3]) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(force_N, "force_N");
        require(torque_Nm, "torque_Nm");
        const enteron::collision::ToolWrench wrench = present_tool(handle, tool).output.wrench;
        for (int c = 0; c < 3; ++c) force_N[c] = wrench.force[c], torque_Nm[c] = wrench.torque[c];
    });
}

ENT_API ent_status ent_tool_state(const ent_scene* scene, int32_t tool, int32_t* out_grasping) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out_grasping, "out_grasping");
        *out_grasping = present_tool(handle, tool).output.grasping ? 1 : 0;
    });
}

ENT_API ent_status ent_tool_read_feedback(const ent_scene* scene, int32_t tool, ent_tool_feedback* out) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out, "out");
        enteron::capi::check_struct_size(
            out->struct_size, {kToolFeedbackFirstSize, kToolFeedbackProxySize, sizeof(ent_tool_feedback)},
            "ent_tool_feedback");
        const PublishedTool published = present_tool(handle, tool);
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
        std::copy(output.stiffness.begin(), output.stiffness.end(), full.stiffness_N_per_m);
        for (int c = 0; c < 3; ++c) {
            full.proxy_position_m[c] = output.proxy.position[c];
            full.commanded_position_m[c] = output.commanded.position[c];
        }
        std::copy(output.commanded.orientation.begin(), output.commanded.orientation.end(), full.orientation_wxyz);
        full.saturated = output.saturated ? 1 : 0;
        std::memcpy(out, &full, out->struct_size);
    });
}

ENT_API ent_status ent_tool_stiffness(const ent_scene* scene, int32_t tool, double K_N_per_m[9]) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(K_N_per_m, "K_N_per_m");
        const std::array<double, 9> stiffness = present_tool(handle, tool).output.stiffness;
        std::copy(stiffness.begin(), stiffness.end(), K_N_per_m);
    });
}

ENT_API ent_status ent_tool_read_stats(const ent_scene* scene, int32_t tool, ent_tool_stats* out) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out, "out");
        enteron::capi::check_struct_size(out->struct_size, {sizeof(ent_tool_stats)}, "ent_tool_stats");
        const PublishedTool published = present_tool(handle, tool);
        const enteron::collision::ToolOutput& output = published.output;
        ent_tool_stats full{};
        full.struct_size = out->struct_size;
        full.grasping = output.grasping ? 1 : 0;
        full.contacts = output.contacts;
        full.energy_in_J = output.stats.energy_in;
        full.energy_out_J = output.stats.energy_out;
        full.limiter_energy_J = output.stats.limiter_energy;
        full.largest_force_change_N = output.stats.largest_force_change;
        full.steps = published.steps;
        std::memcpy(out, &full, out->struct_size);
    });
}

ENT_API ent_status ent_tool_remove(ent_scene* scene, int32_t tool) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        const enteron::capi::DrivingCall driving(handle, "ent_tool_remove");
        mailbox_of(handle, tool);  // NOT_FOUND for an unknown or removed tool
        handle.scene->remove_tool(static_cast<std::size_t>(tool));
    });
}

ENT_API ent_status ent_scene_tool_count(const ent_scene* scene, int32_t* out_count) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out_count, "out_count");
        *out_count = static_cast<int32_t>(handle.scene->tool_channels().present());
    });
}

}  // extern "C"
