// SPDX-License-Identifier: Apache-2.0
// The viewer's end of an LCM session with enteron-lcm-server (docs/lcm.md, docs/viewer.md):
// one thread of its own that receives ENTERON_SESSION, ENTERON_STATE and ENTERON_MESH,
// checks every message before decoding it (ent_lcm_check_message, then the values: finite
// numbers, indices within the mesh, a scene JSON libenteron accepts), and hands the newest
// of each to the render thread through LatestValue (newest wins: neither thread ever waits
// for the other). The same thread sends the tools the mouse drives as tool_command_t every
// 5 ms, like a haptic device's driver: in the device's frame (the session's workspace
// mapping inverted), a sequence number per tool, the deadman pressed.
#pragma once

#include <lcm/lcm.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "../latest_value.h"
#include "../scene_layout.h"
#include "../tool_exchange.h"
#include "axis_tube.h"

namespace viewer {

// A tool in a scene_state_t, scene frame, SI.
struct RemoteTool {
    std::int32_t tool = 0;
    double radius_m = 0.0, length_m = 0.0, max_force_N = 0.0;
    ToolPose commanded, applied;
    double force_N[3] = {}, torque_Nm[3] = {};
    bool grasping = false;
    std::int32_t status = 0;  // tool_feedback_t STATUS_* bits
};

// The STATUS_* bits set in status, in words, comma-separated ("" for none; an unknown bit
// by its value).
std::string describe_tool_status(std::int32_t status);

// A scene_state_t that passed the checks.
struct RemoteState {
    std::int64_t tick = 0;
    double sim_time_s = 0.0;
    double radius_m = 0.0;
    double kinetic_energy_J = 0.0, potential_energy_J = 0.0;
    std::int32_t contacts = 0;
    double max_penetration_m = 0.0;
    std::int64_t steps = 0, substeps = 0, rollbacks = 0;
    std::int32_t step_us = 0;
    std::vector<double> control_points_m;  // x y z per point
    std::vector<double> axis_m;            // x y z per point, evenly in arc length
    std::vector<RemoteTool> tools;
};

// A mesh_t that passed the checks.
struct RemoteMesh {
    std::int64_t tick = 0;
    double sim_time_s = 0.0;
    std::int32_t skin_method = 0;          // ENT_SKIN_*
    MeshArrays arrays;                     // every index < its vertices
};

// A session_t that passed the checks: the scene and the bridge's settings.
struct RemoteScene {
    std::int64_t session_id = 0;
    std::string scene_json;
    SceneLayout layout;
    double tick_s = 0.0, state_hz = 0.0, mesh_hz = 0.0;
    std::int32_t mesh_skin_method = 0;
    double workspace_scale = 1.0;                           // scene m per device unit
    double workspace_rotation_wxyz[4] = {1.0, 0.0, 0.0, 0.0};  // device axes into the scene's
    double workspace_offset_m[3] = {0.0, 0.0, 0.0};
};

// Render thread -> LCM thread: what to send. Only the tools marked driven are commanded
// (a viewer that merely watches sends nothing, and never fights a device for a tool).
struct RemoteCommands {
    ToolCommands commands;                 // scene frame
    bool driven[kMaxTools] = {};
};

// Why the last message was refused, for the status line.
struct Rejection {
    char text[200] = "";
};

class RemoteLink {
public:
    static constexpr int kSendPeriodMs = 5;  // 200 commands/s: well inside the 30 ms watchdog

    // Creates the LCM instance for url, subscribes and starts the thread. Null with a
    // message when LCM refuses the URL.
    static std::unique_ptr<RemoteLink> open(const std::string& url, const std::string& channel_suffix,
                                            std::string& error);
    ~RemoteLink();  // stops the thread and joins it
    RemoteLink(const RemoteLink&) = delete;
    RemoteLink& operator=(const RemoteLink&) = delete;

    // LCM thread -> render thread.
    LatestValue<RemoteScene>& scenes() { return scenes_; }
    LatestValue<RemoteState>& states() { return states_; }
    LatestValue<RemoteMesh>& meshes() { return meshes_; }
    LatestValue<Rejection>& rejections() { return rejections_; }
    // Render thread -> LCM thread.
    LatestValue<RemoteCommands>& commands() { return commands_; }

    // Counters, read from any thread.
    struct Counters {
        std::atomic<std::uint64_t> sessions{0}, states{0}, meshes{0};  // accepted
        std::atomic<std::uint64_t> rejected{0};  // failed a check: never shown, never decoded unchecked
        std::atomic<std::uint64_t> late{0};      // a state or mesh older than one already shown
        std::atomic<std::uint64_t> commands_sent{0};
        std::atomic<std::int64_t> last_state_ns{0};  // steady clock when the newest state arrived
    };
    const Counters& counters() const { return counters_; }

private:
    RemoteLink() = default;
    void run();
    static void on_message(const lcm_recv_buf_t* buffer, const char* channel, void* user);
    void receive(const std::string& channel, const void* bytes, std::size_t size);
    void reject(const std::string& channel, const std::string& why);
    void on_session(const void* bytes, std::size_t size);
    void on_state(const void* bytes, std::size_t size);
    void on_mesh(const void* bytes, std::size_t size);
    void send_commands();

    lcm_t* lcm_ = nullptr;
    std::string session_channel_, state_channel_, mesh_channel_, command_channel_;
    // LCM thread only.
    RemoteScene scene_;
    bool have_scene_ = false;
    std::int64_t newest_state_tick_ = -1, newest_mesh_tick_ = -1;
    RemoteCommands latest_commands_;
    std::int64_t seq_[kMaxTools] = {};
    Counters counters_;
    LatestValue<RemoteScene> scenes_;
    LatestValue<RemoteState> states_;
    LatestValue<RemoteMesh> meshes_;
    LatestValue<Rejection> rejections_;
    LatestValue<RemoteCommands> commands_;
    std::atomic<bool> stop_{false};
    std::thread thread_;  // last: starts after everything above exists
};

// The scene's pose of a tool in the device's frame of a session (docs/lcm.md, workspace
// mapping): p_device = R^T (p_scene - o) / s, q_device = q_R^-1 q_scene.
ToolPose scene_to_device(const RemoteScene& scene, const ToolPose& pose);

}  // namespace viewer
