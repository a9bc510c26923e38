// SPDX-License-Identifier: Apache-2.0
#include "remote_link.h"

#include <enteron/enteron.h>
#include <enteron/enteron_lcm.h>
#include <lcmtypes/enteron_mesh_t.h>
#include <lcmtypes/enteron_scene_state_t.h>
#include <lcmtypes/enteron_session_t.h>
#include <lcmtypes/enteron_tool_command_t.h>
#include <lcmtypes/enteron_tool_feedback_t.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

#include "../clock.h"

namespace viewer {

std::string describe_tool_status(std::int32_t status) {
    static const std::pair<std::int32_t, const char*> names[] = {
        {ENTERON_TOOL_FEEDBACK_T_STATUS_STALE, "stale"},
        {ENTERON_TOOL_FEEDBACK_T_STATUS_NO_COMMAND, "no command"},
        {ENTERON_TOOL_FEEDBACK_T_STATUS_FORCE_LIMITED, "force limited"},
        {ENTERON_TOOL_FEEDBACK_T_STATUS_RATE_LIMITED, "rate limited"},
        {ENTERON_TOOL_FEEDBACK_T_STATUS_UNSTABLE, "unstable"},
        {ENTERON_TOOL_FEEDBACK_T_STATUS_FORCE_DISABLED, "force disabled"}};
    // The reason of a rejection, bits 8-15 (REJECTED_*, 1 to 7).
    static const char* const reasons[] = {"size", "fingerprint", "not finite", "zero quaternion",
                                          "unknown tool", "out of range", "sequence"};
    std::string words;
    for (const auto& [bit, name] : names) {
        if ((status & bit) == 0) continue;
        words += (words.empty() ? "" : ", ") + std::string(name);
        status &= ~bit;
    }
    if ((status & ENTERON_TOOL_FEEDBACK_T_STATUS_COMMANDS_REJECTED) != 0) {
        const int reason = (status & ENTERON_TOOL_FEEDBACK_T_REJECTION_MASK) >> ENTERON_TOOL_FEEDBACK_T_REJECTION_SHIFT;
        words += (words.empty() ? "" : ", ") + std::string("commands rejected (") +
                 (reason >= 1 && reason <= 7 ? reasons[reason - 1] : "reason " + std::to_string(reason)) + ")";
        status &= ~(ENTERON_TOOL_FEEDBACK_T_STATUS_COMMANDS_REJECTED | ENTERON_TOOL_FEEDBACK_T_REJECTION_MASK);
    }
    if (status != 0) words += (words.empty() ? "" : ", ") + std::string("bits ") + std::to_string(status);
    return words;
}

namespace {

// A state more than this many ticks older than the newest one comes from a server that
// started again (its ticks count from 0), not from a slow network.
constexpr std::int64_t kRestartTicks = 1000;
// More tools than this in a message is not a scene anyone simulates.
constexpr std::int32_t kMostTools = 64;

bool finite(const double* values, std::size_t count) {
    return std::all_of(values, values + count, [](double v) { return std::isfinite(v); });
}

// The rows of a decoded float[n][3] array, as doubles; false if one is not finite.
bool copy_rows(float* const* rows, std::int32_t count, std::vector<double>& out) {
    out.resize(3 * static_cast<std::size_t>(count));
    for (std::int32_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c) {
            const double value = rows[i][c];
            if (!std::isfinite(value)) return false;
            out[3 * static_cast<std::size_t>(i) + c] = value;
        }
    return true;
}

bool copy_pose(const double* position, const double* orientation, ToolPose& pose) {
    if (!finite(position, 3) || !finite(orientation, 4)) return false;
    const double norm = std::sqrt(orientation[0] * orientation[0] + orientation[1] * orientation[1] +
                                  orientation[2] * orientation[2] + orientation[3] * orientation[3]);
    if (norm < 1e-6) return false;
    std::copy(position, position + 3, pose.position_m);
    for (int c = 0; c < 4; ++c) pose.orientation_wxyz[c] = orientation[c] / norm;
    return true;
}

// Decodes bytes that ent_lcm_check_message accepted; the decoder's cleanup always runs.
template <class Message, class Use>
bool decode(int (*decoder)(const void*, int, int, Message*), int (*cleanup)(Message*), const void* bytes,
            std::size_t size, Use&& use) {
    Message message{};
    if (size > static_cast<std::size_t>(INT32_MAX) || decoder(bytes, 0, static_cast<int>(size), &message) < 0)
        return false;
    bool used = false;
    try {
        used = use(message);
    } catch (const std::exception&) {  // out of memory for a huge, well-formed message
        used = false;
    }
    cleanup(&message);
    return used;
}

// Whether a message of this tick is older than the newest shown (udpm may reorder), and
// if not, makes it the newest. Far older is a server that started again: its ticks count
// from 0.
bool late(std::int64_t tick, std::int64_t& newest) {
    if (tick <= newest && newest - tick < kRestartTicks) return true;
    newest = tick;
    return false;
}

}  // namespace

ToolPose scene_to_device(const RemoteScene& scene, const ToolPose& pose) {
    const double* r = scene.workspace_rotation_wxyz;
    const Eigen::Quaterniond rotation = Eigen::Quaterniond(r[0], r[1], r[2], r[3]).normalized();
    const Eigen::Vector3d p = Eigen::Map<const Eigen::Vector3d>(pose.position_m) -
                              Eigen::Map<const Eigen::Vector3d>(scene.workspace_offset_m);
    const double* o = pose.orientation_wxyz;
    const Eigen::Quaterniond q = rotation.conjugate() * Eigen::Quaterniond(o[0], o[1], o[2], o[3]);
    ToolPose device;
    Eigen::Map<Eigen::Vector3d>(device.position_m) = rotation.conjugate() * p / scene.workspace_scale;
    device.orientation_wxyz[0] = q.w();
    device.orientation_wxyz[1] = q.x();
    device.orientation_wxyz[2] = q.y();
    device.orientation_wxyz[3] = q.z();
    return device;
}

std::unique_ptr<RemoteLink> RemoteLink::open(const std::string& url, const std::string& channel_suffix,
                                             std::string& error) {
    std::unique_ptr<RemoteLink> link(new RemoteLink());
    link->lcm_ = lcm_create(url.c_str());
    if (link->lcm_ == nullptr) {
        error = "LCM cannot open " + url + " (a provider udpm://, memq:// or file://, and a network that allows it)";
        return nullptr;
    }
    link->session_channel_ = "ENTERON_SESSION" + channel_suffix;
    link->state_channel_ = "ENTERON_STATE" + channel_suffix;
    link->mesh_channel_ = "ENTERON_MESH" + channel_suffix;
    link->command_channel_ = "ENTERON_TOOL_COMMAND" + channel_suffix;
    for (const std::string* channel : {&link->session_channel_, &link->state_channel_, &link->mesh_channel_}) {
        // The raw bytes: nothing is decoded before it has been checked.
        lcm_subscription_t* subscription = lcm_subscribe(link->lcm_, channel->c_str(), &RemoteLink::on_message, link.get());
        if (subscription == nullptr) {
            error = "LCM cannot subscribe to " + *channel + " on " + url;
            lcm_destroy(link->lcm_);
            link->lcm_ = nullptr;
            return nullptr;
        }
    }
    link->thread_ = std::thread(&RemoteLink::run, link.get());
    return link;
}

RemoteLink::~RemoteLink() {
    stop_.store(true);
    if (thread_.joinable()) thread_.join();
    if (lcm_ != nullptr) lcm_destroy(lcm_);
}

void RemoteLink::run() {
    using std::chrono::milliseconds;
    auto next_send = std::chrono::steady_clock::now();
    while (!stop_.load()) {
        const auto now = std::chrono::steady_clock::now();
        const auto wait = std::chrono::duration_cast<milliseconds>(next_send - now).count();
        // A failing provider returns at once: the loop still paces itself by the send period.
        if (lcm_handle_timeout(lcm_, static_cast<int>(std::clamp<long long>(wait, 1, kSendPeriodMs))) < 0)
            std::this_thread::sleep_for(milliseconds(kSendPeriodMs));
        if (std::chrono::steady_clock::now() >= next_send) {
            send_commands();
            next_send += milliseconds(kSendPeriodMs);
            if (next_send < std::chrono::steady_clock::now()) next_send = std::chrono::steady_clock::now() + milliseconds(kSendPeriodMs);
        }
    }
}

void RemoteLink::on_message(const lcm_recv_buf_t* buffer, const char* channel, void* user) {
    // LCM's C code calls this: nothing may be thrown through it.
    try {
        static_cast<RemoteLink*>(user)->receive(channel, buffer->data, buffer->data_size);
    } catch (...) {
        static_cast<RemoteLink*>(user)->counters_.rejected.fetch_add(1);
    }
}

void RemoteLink::receive(const std::string& channel, const void* bytes, std::size_t size) {
    // LCM subscribes by regular expression: a suffix with a '.' in it matches more channels.
    const int type = channel == state_channel_     ? ENT_LCM_SCENE_STATE
                     : channel == mesh_channel_    ? ENT_LCM_MESH
                     : channel == session_channel_ ? ENT_LCM_SESSION
                                                   : -1;
    if (type < 0) return;
    if (ent_lcm_check_message(type, bytes, size) != ENT_OK) return reject(channel, ent_lcm_last_error());
    if (type == ENT_LCM_SCENE_STATE) on_state(bytes, size);
    if (type == ENT_LCM_MESH) on_mesh(bytes, size);
    if (type == ENT_LCM_SESSION) on_session(bytes, size);
}

void RemoteLink::reject(const std::string& channel, const std::string& why) {
    counters_.rejected.fetch_add(1);
    Rejection rejection;
    std::snprintf(rejection.text, sizeof rejection.text, "%s: %s", channel.c_str(), why.c_str());
    rejections_.publish(rejection);
}

void RemoteLink::on_session(const void* bytes, std::size_t size) {
    std::string why = "cannot decode";
    const bool ok = decode(&enteron_session_t_decode, &enteron_session_t_decode_cleanup, bytes, size,
                           [&](const enteron_session_t& m) {
        if (!(m.workspace_scale > 0.0) || !std::isfinite(m.workspace_scale) || !finite(m.workspace_rotation_wxyz, 4) ||
            !finite(m.workspace_offset_m, 3) || !(m.tick_s > 0.0) || !std::isfinite(m.tick_s) ||
            std::abs(m.workspace_rotation_wxyz[0]) + std::abs(m.workspace_rotation_wxyz[1]) +
                    std::abs(m.workspace_rotation_wxyz[2]) + std::abs(m.workspace_rotation_wxyz[3]) < 1e-6) {
            why = "a workspace mapping or tick that is not a number, zero or negative";
            return false;
        }
        const std::string json = m.scene_json;
        if (have_scene_ && m.session_id == scene_.session_id && json == scene_.scene_json) return true;  // once a second
        // A scene the library accepts, read as the local viewer reads its own.
        ent_scene* scene = nullptr;
        const ent_status status = ent_scene_create_json(json.data(), json.size(), &scene);
        ent_scene_destroy(scene);
        if (status != ENT_OK) {
            why = std::string("its scene_json: ") + ent_last_error();
            return false;
        }
        RemoteScene next;
        if (!read_scene_layout(json, next.layout, why)) return false;
        if (next.layout.tools.size() != static_cast<std::size_t>(std::max(0, m.num_tools))) {
            why = "num_tools differs from the scene's tools";
            return false;
        }
        next.session_id = m.session_id;
        next.scene_json = json;
        next.tick_s = m.tick_s;
        next.state_hz = m.state_hz;
        next.mesh_hz = m.mesh_hz;
        next.mesh_skin_method = m.mesh_skin_method;
        next.workspace_scale = m.workspace_scale;
        std::copy(m.workspace_rotation_wxyz, m.workspace_rotation_wxyz + 4, next.workspace_rotation_wxyz);
        std::copy(m.workspace_offset_m, m.workspace_offset_m + 3, next.workspace_offset_m);
        if (have_scene_ && next.session_id != scene_.session_id) newest_state_tick_ = newest_mesh_tick_ = -1;
        scene_ = next;
        have_scene_ = true;
        scenes_.publish(next);
        return true;
    });
    if (!ok) return reject(session_channel_, why);
    counters_.sessions.fetch_add(1);
}

void RemoteLink::on_state(const void* bytes, std::size_t size) {
    std::string why = "cannot decode";
    bool was_late = false;
    const bool ok = decode(&enteron_scene_state_t_decode, &enteron_scene_state_t_decode_cleanup, bytes, size,
                           [&](const enteron_scene_state_t& m) {
        if (m.num_tools > kMostTools) {
            why = "more than 64 tools";
            return false;
        }
        if (m.num_axis_points < 2) {
            why = "fewer than 2 axis points";
            return false;
        }
        RemoteState state;
        state.tick = m.tick;
        state.sim_time_s = m.sim_time_s;
        state.radius_m = m.radius_m;
        state.kinetic_energy_J = m.kinetic_energy_J;
        state.potential_energy_J = m.potential_energy_J;
        state.contacts = m.contacts;
        state.max_penetration_m = m.max_penetration_m;
        state.steps = m.steps;
        state.substeps = m.substeps;
        state.rollbacks = m.rollbacks;
        state.step_us = m.step_us;
        const double numbers[] = {m.sim_time_s, m.radius_m, m.kinetic_energy_J, m.potential_energy_J,
                                  m.max_penetration_m};
        if (!finite(numbers, 5) || !(m.radius_m > 0.0) || m.tick < 0 || m.contacts < 0 || m.steps < 0) {
            why = "a time, radius, energy or count that is not finite or negative";
            return false;
        }
        if (!copy_rows(m.control_points_m, m.num_control_points, state.control_points_m) ||
            !copy_rows(m.axis_m, m.num_axis_points, state.axis_m)) {
            why = "a control point or axis point that is not finite";
            return false;
        }
        for (std::int32_t i = 0; i < m.num_tools; ++i) {
            const enteron_tool_state_t& t = m.tools[i];
            RemoteTool tool;
            tool.tool = t.tool;
            tool.radius_m = t.radius_m;
            tool.length_m = t.length_m;
            tool.max_force_N = t.max_force_N;
            const double sizes[] = {t.radius_m, t.length_m, t.max_force_N};
            if (t.tool < 0 || t.tool >= kMostTools || !finite(sizes, 3) || t.radius_m < 0.0 || t.length_m < 0.0 ||
                !copy_pose(t.commanded_position_m, t.commanded_orientation_wxyz, tool.commanded) ||
                !copy_pose(t.applied_position_m, t.applied_orientation_wxyz, tool.applied) ||
                !finite(t.force_N, 3) || !finite(t.torque_Nm, 3)) {
                why = "tool " + std::to_string(i) + ": an index, size, pose or force that is not valid";
                return false;
            }
            std::copy(t.force_N, t.force_N + 3, tool.force_N);
            std::copy(t.torque_Nm, t.torque_Nm + 3, tool.torque_Nm);
            tool.grasping = t.grasping != 0;
            tool.status = t.status;
            state.tools.push_back(tool);
        }
        was_late = late(state.tick, newest_state_tick_);
        if (!was_late) states_.publish(state);
        return true;
    });
    if (!ok) return reject(state_channel_, why);
    if (was_late) {
        counters_.late.fetch_add(1);
        return;
    }
    counters_.states.fetch_add(1);
    counters_.last_state_ns.store(steady_ns());
}

void RemoteLink::on_mesh(const void* bytes, std::size_t size) {
    std::string why = "cannot decode";
    bool was_late = false;
    const bool ok = decode(&enteron_mesh_t_decode, &enteron_mesh_t_decode_cleanup, bytes, size,
                           [&](const enteron_mesh_t& m) {
        if (m.skin_method < ENT_SKIN_TUBE || m.skin_method > ENT_SKIN_CONVOLUTION || !std::isfinite(m.sim_time_s)) {
            why = "an unknown skin method or a time that is not finite";
            return false;
        }
        RemoteMesh mesh;
        mesh.tick = m.tick;
        mesh.sim_time_s = m.sim_time_s;
        mesh.skin_method = m.skin_method;
        const auto vertices = static_cast<std::size_t>(m.num_vertices);
        mesh.arrays.positions_m.resize(3 * vertices);
        mesh.arrays.normals.resize(3 * vertices);
        mesh.arrays.axis_u.assign(m.axis_u, m.axis_u + vertices);
        for (std::size_t v = 0; v < vertices; ++v)
            for (int c = 0; c < 3; ++c) {
                mesh.arrays.positions_m[3 * v + c] = m.positions_m[v][c];
                mesh.arrays.normals[3 * v + c] = m.normals[v][c];
            }
        const auto finite_float = [](float x) { return std::isfinite(x); };
        if (!std::all_of(mesh.arrays.positions_m.begin(), mesh.arrays.positions_m.end(), finite_float) ||
            !std::all_of(mesh.arrays.normals.begin(), mesh.arrays.normals.end(), finite_float) ||
            !std::all_of(mesh.arrays.axis_u.begin(), mesh.arrays.axis_u.end(), finite_float)) {
            why = "a vertex, normal or u that is not finite";
            return false;
        }
        // An index beyond the vertices would make the renderer read past them.
        mesh.arrays.indices.resize(3 * static_cast<std::size_t>(m.num_triangles));
        for (std::int32_t t = 0; t < m.num_triangles; ++t)
            for (int c = 0; c < 3; ++c) {
                const std::int32_t index = m.triangles[t][c];
                if (index < 0 || index >= m.num_vertices) {
                    why = "triangle " + std::to_string(t) + " names vertex " + std::to_string(index) + " of " +
                          std::to_string(m.num_vertices);
                    return false;
                }
                mesh.arrays.indices[3 * static_cast<std::size_t>(t) + c] = static_cast<std::uint32_t>(index);
            }
        was_late = late(mesh.tick, newest_mesh_tick_);
        if (!was_late) meshes_.publish(mesh);
        return true;
    });
    if (!ok) return reject(mesh_channel_, why);
    if (was_late)
        counters_.late.fetch_add(1);
    else
        counters_.meshes.fetch_add(1);
}

void RemoteLink::send_commands() {
    commands_.take(latest_commands_);
    if (!have_scene_) return;  // no workspace mapping yet: nothing can be said in device units
    const ToolCommands& commands = latest_commands_.commands;
    const std::uint32_t tools = std::min<std::uint32_t>(commands.count, static_cast<std::uint32_t>(scene_.layout.tools.size()));
    const auto utime = std::chrono::duration_cast<std::chrono::microseconds>(
                           std::chrono::system_clock::now().time_since_epoch()).count();
    for (std::uint32_t i = 0; i < tools && i < kMaxTools; ++i) {
        if (!latest_commands_.driven[i]) continue;
        const ToolPose device = scene_to_device(scene_, commands.target[i]);
        enteron_tool_command_t command{};
        command.utime = utime;
        command.seq = ++seq_[i];
        command.tool = static_cast<std::int32_t>(i);
        std::copy(device.position_m, device.position_m + 3, command.position_m);
        std::copy(device.orientation_wxyz, device.orientation_wxyz + 4, command.orientation_wxyz);
        command.grasp = commands.grasp[i] ? 1 : 0;
        command.force_enable = 1;  // the mouse has no deadman: it is always pressed
        if (enteron_tool_command_t_publish(lcm_, command_channel_.c_str(), &command) == 0)
            counters_.commands_sent.fetch_add(1);
    }
}

}  // namespace viewer
