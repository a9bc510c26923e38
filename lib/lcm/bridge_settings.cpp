// SPDX-License-Identifier: Apache-2.0
#include "lcm/bridge_settings.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "base/error.h"
#include "capi/struct_size.h"

namespace enteron::lcm {

namespace {

[[noreturn]] void bad(const char* field, const char* rule, double value) {
    char message[200];
    std::snprintf(message, sizeof message, "desc.%s must be %s, got %g", field, rule, value);
    throw Error(ErrorCode::invalid_argument, message);
}

void check_range(const char* field, double value, double low, bool low_open, double high) {
    const bool above_low = low_open ? value > low : value >= low;
    if (!std::isfinite(value) || !above_low || value > high) {
        char rule[96];
        std::snprintf(rule, sizeof rule, "in %s%g, %g]", low_open ? "(" : "[", low, high);
        bad(field, rule, value);
    }
}

void check_positive(const char* field, double value) {
    if (!std::isfinite(value) || !(value > 0.0)) bad(field, "finite and > 0", value);
}

}  // namespace

ent_lcm_bridge_desc default_bridge_desc() {
    ent_lcm_bridge_desc desc;
    std::memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc;
    desc.tick_s = 0.001;
    desc.watchdog_s = 0.030;
    desc.state_hz = 60.0;
    desc.state_axis_points = 200;
    desc.mesh_hz = 0.0;
    desc.mesh_skin_method = ENT_SKIN_CONVOLUTION;
    desc.force_ramp_s = 0.1;
    desc.max_tool_speed_m_per_s = 1.0;
    desc.max_tool_angular_speed_rad_per_s = 10.0;
    desc.workspace_scale = 1.0;
    desc.workspace_rotation_wxyz[0] = 1.0;
    desc.force_scale = 1.0;
    return desc;
}

BridgeSettings bridge_settings(const ent_lcm_bridge_desc& given) {
    capi::check_struct_size(given.struct_size, {sizeof(ent_lcm_bridge_desc)}, "ent_lcm_bridge_desc");
    const ent_lcm_bridge_desc& d = given;
    if (d.scene_json == nullptr) throw Error(ErrorCode::invalid_argument, "desc.scene_json must not be NULL");
    check_range("tick_s", d.tick_s, 0.0, true, 0.1);
    check_range("watchdog_s", d.watchdog_s, 0.0, true, 10.0);
    check_range("state_hz", d.state_hz, 0.0, false, 1000.0);
    if (d.state_axis_points < 2 || d.state_axis_points > 100000)
        bad("state_axis_points", "in [2, 100000]", d.state_axis_points);
    check_range("mesh_hz", d.mesh_hz, 0.0, false, 100.0);
    if (d.mesh_skin_method < ENT_SKIN_TUBE || d.mesh_skin_method > ENT_SKIN_CONVOLUTION)
        bad("mesh_skin_method", "an ENT_SKIN_* (0, 1 or 2)", d.mesh_skin_method);
    check_range("force_ramp_s", d.force_ramp_s, 0.0, false, 10.0);
    check_positive("max_tool_speed_m_per_s", d.max_tool_speed_m_per_s);
    check_positive("max_tool_angular_speed_rad_per_s", d.max_tool_angular_speed_rad_per_s);
    if (!std::isfinite(d.device_max_force) || d.device_max_force < 0.0)
        bad("device_max_force", "finite and >= 0", d.device_max_force);
    if (!std::isfinite(d.max_force_change_per_tick) || d.max_force_change_per_tick < 0.0)
        bad("max_force_change_per_tick", "finite and >= 0", d.max_force_change_per_tick);
    check_positive("workspace_scale", d.workspace_scale);
    check_positive("force_scale", d.force_scale);
    const Eigen::Quaterniond rotation(d.workspace_rotation_wxyz[0], d.workspace_rotation_wxyz[1],
                                      d.workspace_rotation_wxyz[2], d.workspace_rotation_wxyz[3]);
    if (!rotation.coeffs().allFinite() || rotation.norm() < 1e-6)
        throw Error(ErrorCode::invalid_argument, "desc.workspace_rotation_wxyz must be a finite, non-zero quaternion");
    const Eigen::Vector3d offset(d.workspace_offset_m[0], d.workspace_offset_m[1], d.workspace_offset_m[2]);
    if (!offset.allFinite()) throw Error(ErrorCode::invalid_argument, "desc.workspace_offset_m must be finite");
    if (d.realtime_priority < 0 || d.realtime_priority > 99)
        bad("realtime_priority", "in [0, 99]", d.realtime_priority);
    if (d.callbacks != nullptr)
        capi::check_struct_size(d.callbacks->struct_size, {sizeof(ent_callbacks)}, "desc.callbacks (ent_callbacks)");

    BridgeSettings s;
    s.scene_json.assign(d.scene_json, d.scene_json_length);
    s.has_callbacks = d.callbacks != nullptr;
    if (s.has_callbacks) s.callbacks = *d.callbacks;  // the one released size, checked above
    s.lcm_url = d.lcm_url != nullptr ? d.lcm_url : ENT_LCM_DEFAULT_URL;
    s.network = !s.lcm_url.empty();
    s.channel_suffix = d.channel_suffix != nullptr ? d.channel_suffix : "";
    s.journal_path = d.journal_path != nullptr ? d.journal_path : "";
    s.desc = d;
    s.desc.scene_json = nullptr;
    s.desc.callbacks = nullptr;
    s.desc.lcm_url = nullptr;
    s.desc.channel_suffix = nullptr;
    s.desc.journal_path = nullptr;
    s.mapping = WorkspaceMapping(d.workspace_scale, rotation, offset, d.force_scale);
    return s;
}

SafetyLimits BridgeSettings::limits() const {
    SafetyLimits limits;
    limits.tick_s = desc.tick_s;
    limits.watchdog_ns = static_cast<int64_t>(std::llround(desc.watchdog_s * 1e9));
    limits.force_ramp_s = desc.force_ramp_s;
    limits.max_speed_m_per_s = desc.max_tool_speed_m_per_s;
    limits.max_angular_speed_rad_per_s = desc.max_tool_angular_speed_rad_per_s;
    limits.device_max_force = desc.device_max_force;
    limits.max_force_change_per_tick = desc.max_force_change_per_tick;
    return limits;
}

}  // namespace enteron::lcm
