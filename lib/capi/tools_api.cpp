// The tool entry points of the C API: surgical instruments that push and grasp the bowel.
#include <cstring>
#include <string>

#include "capi/call_guard.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "collision/tool.h"

static_assert(ENT_EFFECT_TOOLS == static_cast<int>(enteron::EffectId::tools));

namespace {

using enteron::Error;
using enteron::ErrorCode;

// The tool index of an id, or NOT_FOUND naming it.
std::size_t tool_index(const enteron::scene::Scene& scene, int32_t tool) {
    if (tool < 0 || static_cast<std::size_t>(tool) >= scene.tool_count())
        throw Error(ErrorCode::not_found, "tool " + std::to_string(tool) + " does not exist (the scene has " +
                                              std::to_string(scene.tool_count()) + " tools)");
    return static_cast<std::size_t>(tool);
}

enteron::scene::Scene& scene_of(ent_scene* scene) { return *enteron::capi::handle_of(scene)->scene; }

}  // namespace

extern "C" {

ENT_API ent_status ent_tool_desc_init(ent_tool_desc* desc, uint32_t struct_size) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(desc, "desc");
        enteron::capi::check_struct_size(struct_size, {sizeof(ent_tool_desc)}, "ent_tool_desc");
        const enteron::collision::ToolSettings settings;
        ent_tool_desc defaults;
        std::memset(&defaults, 0, sizeof defaults);
        defaults.struct_size = struct_size;
        defaults.radius_m = settings.radius;
        defaults.length_m = settings.length;
        defaults.max_force_N = settings.max_force;
        defaults.grasp_margin_m = settings.grasp_margin;
        defaults.grasp_stiffness_N_per_m = settings.grasp_stiffness;
        defaults.grasp_damping_N_s_per_m = settings.grasp_damping;
        defaults.orientation_wxyz[0] = 1.0;
        std::memcpy(desc, &defaults, struct_size);
    });
}

ENT_API ent_status ent_tool_add(ent_scene* scene, const ent_tool_desc* desc, int32_t* out_tool) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(scene, "scene");
        enteron::capi::require(desc, "desc");
        enteron::capi::check_struct_size(desc->struct_size, {sizeof(ent_tool_desc)}, "ent_tool_desc");
        enteron::collision::ToolConfig tool;
        tool.settings.radius = desc->radius_m;
        tool.settings.length = desc->length_m;
        tool.settings.max_force = desc->max_force_N;
        tool.settings.grasp_margin = desc->grasp_margin_m;
        tool.settings.grasp_stiffness = desc->grasp_stiffness_N_per_m;
        tool.settings.grasp_damping = desc->grasp_damping_N_s_per_m;
        for (int c = 0; c < 3; ++c) tool.pose.position[c] = desc->position_m[c];
        for (int c = 0; c < 4; ++c) tool.pose.orientation[c] = desc->orientation_wxyz[c];
        enteron::collision::validate_tool_settings(tool.settings, "desc", ErrorCode::invalid_argument);
        tool.pose = enteron::collision::normalized_pose(tool.pose, "desc", ErrorCode::invalid_argument);
        const std::size_t index = scene_of(scene).add_tool(tool);
        if (out_tool != nullptr) *out_tool = static_cast<int32_t>(index);
    });
}

ENT_API ent_status ent_tool_set_pose(ent_scene* scene, int32_t tool, const double position_m[3],
                                     const double orientation_wxyz[4]) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(scene, "scene");
        enteron::capi::require(position_m, "position_m");
        enteron::capi::require(orientation_wxyz, "orientation_wxyz");
        enteron::scene::Scene& s = scene_of(scene);
        const std::size_t index = tool_index(s, tool);
        enteron::collision::ToolPose pose;
        for (int c = 0; c < 3; ++c) pose.position[c] = position_m[c];
        for (int c = 0; c < 4; ++c) pose.orientation[c] = orientation_wxyz[c];
        s.set_tool_pose(index, enteron::collision::normalized_pose(pose, "pose", ErrorCode::invalid_argument));
    });
}

ENT_API ent_status ent_tool_wrench(const ent_scene* scene, int32_t tool, double force_N[3], double torque_Nm[3]) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(scene, "scene");
        enteron::capi::require(force_N, "force_N");
        enteron::capi::require(torque_Nm, "torque_Nm");
        const enteron::scene::Scene& s = enteron::capi::scene_of_handle(scene);
        s.tool_wrench(tool_index(s, tool), force_N, torque_Nm);
    });
}

ENT_API ent_status ent_tool_grasp(ent_scene* scene, int32_t tool) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(scene, "scene");
        enteron::scene::Scene& s = scene_of(scene);
        s.grasp(tool_index(s, tool));
    });
}

ENT_API ent_status ent_tool_release(ent_scene* scene, int32_t tool) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(scene, "scene");
        enteron::scene::Scene& s = scene_of(scene);
        s.release(tool_index(s, tool));
    });
}

ENT_API ent_status ent_tool_state(const ent_scene* scene, int32_t tool, int32_t* out_grasping) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(scene, "scene");
        enteron::capi::require(out_grasping, "out_grasping");
        const enteron::scene::Scene& s = enteron::capi::scene_of_handle(scene);
        *out_grasping = s.grasping(tool_index(s, tool)) ? 1 : 0;
    });
}

}  // extern "C"
