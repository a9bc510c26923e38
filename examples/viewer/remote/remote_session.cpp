// SPDX-License-Identifier: Apache-2.0
#include "remote_session.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "../clock.h"
#include "axis_samples.h"

namespace viewer {

namespace {

// Sides of the tube drawn around the axis when the server sends no mesh.
constexpr int kTubeSides = 16;
// A server mesh older than this (simulated time behind the state) gives way to the tube,
// which follows every state: a server that stopped sending meshes does not freeze the bowel.
constexpr double kMeshKeptS = 1.0;

bool same_command(const ToolCommands& a, const ToolCommands& b, std::uint32_t i) {
    return a.grasp[i] == b.grasp[i] &&
           std::memcmp(a.target[i].position_m, b.target[i].position_m, sizeof a.target[i].position_m) == 0 &&
           std::memcmp(a.target[i].orientation_wxyz, b.target[i].orientation_wxyz, sizeof a.target[i].orientation_wxyz) == 0;
}

// The viewer's mesh view of arrays this session keeps until the next read.
void point_at(const MeshArrays& arrays, double time_s, ent_mesh_view& view) {
    view.vertex_count = static_cast<std::uint32_t>(arrays.axis_u.size());
    view.triangle_count = static_cast<std::uint32_t>(arrays.indices.size() / 3);
    view.positions_xyz_m = arrays.positions_m.data();
    view.normals_xyz = arrays.normals.data();
    view.axis_u = arrays.axis_u.data();
    view.indices = arrays.indices.data();
    view.time_s = time_s;
}

}  // namespace

std::unique_ptr<RemoteSession> RemoteSession::open(const std::string& url, const std::string& channel_suffix,
                                                   std::string& error) {
    std::unique_ptr<RemoteSession> session(new RemoteSession());
    session->link_ = RemoteLink::open(url, channel_suffix, error);
    if (!session->link_) return nullptr;
    session->url_ = url;
    session->name_ = "enteron-lcm-server at " + url + (channel_suffix.empty() ? "" : " (suffix " + channel_suffix + ")");
    ent_skin_desc_default(&session->skin_);
    session->skin_.method = ENT_SKIN_TUBE;
    return session;
}

bool RemoteSession::reset(std::string&) {
    // The scene is the server's: the viewer lets go of the tools and keeps watching.
    baseline_set_ = false;
    std::fill(std::begin(outgoing_.driven), std::end(outgoing_.driven), false);
    link_->commands().publish(outgoing_);
    return true;
}

bool RemoteSession::set_skin(const ent_skin_desc&, std::string& error) {
    error = "the server chooses the mesh (enteron-lcm-server --mesh-hz, --mesh-skin); without one the viewer draws a "
            "tube around the axis";
    return false;
}

bool RemoteSession::at_gate(double time_s) {
    // The server keeps its own time: a capture takes a frame every 1 / fps of wall time.
    if (!capture_started_) {
        capture_start_ = std::chrono::steady_clock::now();
        capture_started_ = true;
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - capture_start_).count() >= time_s;
}

void RemoteSession::send(const ToolCommands& commands) {
    if (layout_generation_ == 0) return;  // no scene yet: no tools to drive
    if (!baseline_set_) {
        baseline_ = commands;
        baseline_set_ = true;
    }
    for (std::uint32_t i = 0; i < commands.count && i < kMaxTools; ++i)
        if (!same_command(commands, baseline_, i)) outgoing_.driven[i] = true;
    outgoing_.commands = commands;
    link_->commands().publish(outgoing_);
}

void RemoteSession::take_messages(FrameState& frame) {
    RemoteScene scene;
    if (link_->scenes().take(scene)) {
        scene_ = std::move(scene);
        layout_ = scene_.layout;
        ++layout_generation_;
        baseline_set_ = false;  // the viewer resets its tools to the new layout
        std::fill(std::begin(outgoing_.driven), std::end(outgoing_.driven), false);
        skin_.method = scene_.mesh_hz > 0.0 ? scene_.mesh_skin_method : ENT_SKIN_TUBE;
    }
    frame.new_steps.clear();
    RemoteState state;
    if (link_->states().take(state)) {
        state_ = std::move(state);
        have_state_ = true;
        // One plot sample per state (the server's 60 Hz, not its 1 kHz).
        StepSample sample;
        sample.time_s = state_.sim_time_s;
        sample.step_us = static_cast<float>(state_.step_us);
        for (const RemoteTool& tool : state_.tools)
            if (tool.tool >= 0 && static_cast<std::uint32_t>(tool.tool) < kMaxTools)
                for (int c = 0; c < 3; ++c) sample.force_N[tool.tool][c] = static_cast<float>(tool.force_N[c]);
        frame.new_steps.push_back(sample);
    }
    RemoteMesh mesh;
    if (link_->meshes().take(mesh)) {
        mesh_ = std::move(mesh);
        have_mesh_ = true;
    }
    Rejection rejection;
    if (link_->rejections().take(rejection)) last_rejection_ = rejection.text;
}

void RemoteSession::fill_mesh(FrameState& frame) {
    frame.mesh = ent_mesh_view{};
    frame.mesh.struct_size = sizeof frame.mesh;
    const bool use_mesh = have_mesh_ && (!have_state_ || state_.sim_time_s - mesh_.sim_time_s < kMeshKeptS);
    if (use_mesh) {
        point_at(mesh_.arrays, mesh_.sim_time_s, frame.mesh);
        skin_.method = mesh_.skin_method;
        return;
    }
    if (!have_state_) return;
    if (tube_tick_ != state_.tick) {
        make_axis_tube(state_.axis_m, state_.radius_m, kTubeSides, tube_);
        tube_tick_ = state_.tick;
    }
    point_at(tube_, state_.sim_time_s, frame.mesh);
    skin_.method = ENT_SKIN_TUBE;
}

void RemoteSession::read(const FrameRequest& request, FrameState& frame) {
    take_messages(frame);
    frame.dropped_steps = 0;
    frame.paused = false;
    frame.gate_reached_s = -1.0;
    frame.skin_update_ms = 0.0;
    fill_mesh(frame);

    frame.time_s = state_.sim_time_s;
    frame.stats = ent_stats{};
    frame.stats.struct_size = sizeof frame.stats;
    frame.stats.control_points = static_cast<std::uint32_t>(state_.control_points_m.size() / 3);
    frame.stats.time_s = state_.sim_time_s;
    frame.stats.steps = static_cast<std::uint64_t>(std::max<std::int64_t>(0, state_.steps));
    frame.stats.substeps = static_cast<std::uint64_t>(std::max<std::int64_t>(0, state_.substeps));
    frame.stats.rollbacks = static_cast<std::uint64_t>(std::max<std::int64_t>(0, state_.rollbacks));
    frame.stats.kinetic_energy_J = state_.kinetic_energy_J;
    frame.stats.potential_energy_J = state_.potential_energy_J;
    frame.stats.contacts = static_cast<std::uint32_t>(std::max(0, state_.contacts));
    frame.stats.max_penetration_m = state_.max_penetration_m;
    frame.stats.last_step_ns = 1000u * static_cast<std::uint64_t>(std::max(0, state_.step_us));
    for (std::int32_t effect = 0; effect < ENT_EFFECT_COUNT; ++effect) {  // not sent by the server
        frame.effects[effect] = ent_effect_stats{};
        frame.effects[effect].struct_size = sizeof(ent_effect_stats);
    }

    // The tools by their index in the scene; the pose drawn is the one the scene used.
    frame.tool_count = 0;
    for (const RemoteTool& tool : state_.tools) {
        if (tool.tool < 0 || static_cast<std::uint32_t>(tool.tool) >= kMaxTools) continue;
        const auto i = static_cast<std::uint32_t>(tool.tool);
        ToolReadback& readback = frame.tools[i];
        readback.pose = tool.applied;
        readback.feedback = ent_tool_feedback{};
        readback.feedback.struct_size = sizeof readback.feedback;
        readback.feedback.grasping = tool.grasping ? 1 : 0;
        std::copy(tool.force_N, tool.force_N + 3, readback.feedback.force_N);
        std::copy(tool.torque_Nm, tool.torque_Nm + 3, readback.feedback.torque_Nm);
        readback.feedback.time_s = state_.sim_time_s;
        readback.feedback.steps = frame.stats.steps;
        frame.tool_count = std::max(frame.tool_count, i + 1);
    }
    if (!state_.tools.empty() && state_.tools[0].tool == 0) {
        const double* p = state_.tools[0].applied.position_m;
        if (!tool0_seen_) std::copy(p, p + 3, tool0_start_m);
        tool0_seen_ = true;
        const double move = std::sqrt((p[0] - tool0_start_m[0]) * (p[0] - tool0_start_m[0]) +
                                      (p[1] - tool0_start_m[1]) * (p[1] - tool0_start_m[1]) +
                                      (p[2] - tool0_start_m[2]) * (p[2] - tool0_start_m[2]));
        tool0_largest_move_m_ = std::max(tool0_largest_move_m_, move);
    }

    frame.axis_xyz_m.clear();
    frame.control_points_xyz_m.clear();
    // The spheres' centres are not in the stream: the axis resampled at their count.
    frame.spheres_xyz_m.clear();
    if (request.spheres) resample_evenly(state_.axis_m, layout_.collision_spheres, frame.spheres_xyz_m);
    if (request.axis) frame.axis_xyz_m = state_.axis_m;
    if (request.control_points) frame.control_points_xyz_m = state_.control_points_m;

    const RemoteLink::Counters& counters = link_->counters();
    LinkStatus& link = frame.link;
    link.remote = true;
    link.url = url_;
    link.sessions = counters.sessions.load();
    link.states = counters.states.load();
    link.meshes = counters.meshes.load();
    link.rejected = counters.rejected.load();
    link.late = counters.late.load();
    link.commands_sent = counters.commands_sent.load();
    link.last_rejection = last_rejection_;
    link.tool0_largest_move_m = tool0_largest_move_m_;
    for (std::string& status : link.tool_status) status.clear();
    for (const RemoteTool& tool : state_.tools)
        if (tool.tool >= 0 && static_cast<std::uint32_t>(tool.tool) < kMaxTools)
            link.tool_status[tool.tool] = describe_tool_status(tool.status);
    std::copy(outgoing_.commands.target[0].position_m, outgoing_.commands.target[0].position_m + 3, link.tool0_sent_m);
    if (!state_.tools.empty() && state_.tools[0].tool == 0)
        std::copy(state_.tools[0].commanded.position_m, state_.tools[0].commanded.position_m + 3, link.tool0_commanded_m);
    link.age_s = link.states > 0 ? 1e-9 * static_cast<double>(steady_ns() - counters.last_state_ns.load()) : -1.0;
    // A server that sends few states (--state-hz 1) is not stale between two of them.
    const double stale_s = scene_.state_hz > 0.0 ? std::max(kStaleAfterS, 3.0 / scene_.state_hz) : kStaleAfterS;
    link.state = link.states == 0          ? LinkStatus::State::waiting
                 : link.age_s > stale_s    ? LinkStatus::State::stale
                                           : LinkStatus::State::live;
}

}  // namespace viewer
