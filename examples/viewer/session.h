// SPDX-License-Identifier: Apache-2.0
// Where the picture comes from and where the tool commands go. The viewer draws whatever a
// Session gives it once a frame and sends it the tools' targets; it does not know whether
// the scene runs here (LocalSession: a physics thread and a skin in this process) or
// somewhere else (RemoteSession: enteron-lcm-server's state and mesh over LCM, the tools
// sent back as tool_command_t).
#pragma once

#include <enteron/enteron.h>

#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "physics_thread.h"
#include "scene_layout.h"
#include "tool_exchange.h"

namespace viewer {

// The ENT_SKIN_* methods' names, as the command line spells them (--skin), by their value.
inline constexpr const char* kSkinMethodNames[] = {"tube", "point_skeleton", "convolution"};

// An ent_skin_desc.method's name ("?" for none of them).
inline const char* skin_method_name(std::int32_t method) {
    return method >= 0 && method < 3 ? kSkinMethodNames[method] : "?";
}

// The ENT_SKIN_* value a name stands for, or -1.
inline std::int32_t skin_method_named(const std::string& name) {
    for (std::int32_t method = 0; method < 3; ++method)
        if (name == kSkinMethodNames[method]) return method;
    return -1;
}

// The ENT_ERROR_* name of a status, as enteron.h spells it.
inline const char* status_name(ent_status status) {
    switch (status) {
        case ENT_OK: return "ENT_OK";
        case ENT_ERROR_INVALID_ARGUMENT: return "ENT_ERROR_INVALID_ARGUMENT";
        case ENT_ERROR_VERSION: return "ENT_ERROR_VERSION";
        case ENT_ERROR_PARSE: return "ENT_ERROR_PARSE";
        case ENT_ERROR_INVALID_SCENE: return "ENT_ERROR_INVALID_SCENE";
        case ENT_ERROR_UNSTABLE: return "ENT_ERROR_UNSTABLE";
        case ENT_ERROR_OUT_OF_MEMORY: return "ENT_ERROR_OUT_OF_MEMORY";
        case ENT_ERROR_NOT_FOUND: return "ENT_ERROR_NOT_FOUND";
        case ENT_ERROR_BUFFER_TOO_SMALL: return "ENT_ERROR_BUFFER_TOO_SMALL";
        case ENT_ERROR_INTERNAL: return "ENT_ERROR_INTERNAL";
        case ENT_ERROR_BUSY: return "ENT_ERROR_BUSY";
        default: return "ENT_ERROR_?";
    }
}

// A failed library call, as the status line shows it.
struct Problem {
    std::uint64_t count = 0;     // failures so far (a change means a new one)
    ent_status status = ENT_OK;
    std::string call;            // "ent_scene_step"
    std::string message;         // its ent_last_error()
    double time_s = 0.0;         // simulated time it happened at
};

// What to read besides the mesh and the stats (each costs a copy from the snapshot).
struct FrameRequest {
    bool axis = false;
    bool control_points = false;
    bool spheres = false;
};

// A remote session's connection (remote/remote_session.h); remote false for a local one.
struct LinkStatus {
    enum class State { waiting, live, stale };  // no state yet; a fresh one; none for a while
    bool remote = false;
    State state = State::waiting;
    std::string url;
    double age_s = -1.0;                   // wall time since the newest state arrived
    std::uint64_t sessions = 0, states = 0, meshes = 0;  // messages accepted
    std::uint64_t rejected = 0;            // failed a check: counted, never shown
    std::uint64_t late = 0;                // older than one already shown: dropped
    std::uint64_t commands_sent = 0;       // tool_command_t
    std::string last_rejection;            // "CHANNEL: why"
    double tool0_largest_move_m = 0.0;     // the server's tool 0 from where it was first seen
    double tool0_sent_m[3] = {};           // tool 0's target as sent (scene frame, before the mapping)
    double tool0_commanded_m[3] = {};      // the server's newest accepted command for it, mapped back
    // Each tool's tool_feedback_t STATUS_* bits in the newest state, in words ("stale, force
    // limited"; "" when none is set): why a device gets no force or a clamped one.
    std::string tool_status[kMaxTools];
};

inline const char* link_state_name(LinkStatus::State state) {
    switch (state) {
        case LinkStatus::State::waiting: return "no messages yet";
        case LinkStatus::State::live: return "live";
        default: return "stale";
    }
}

// "live (12 ms), 340 states, 0 meshes, 2 rejected, 0 late, 1200 commands sent": for the
// status line and the summary a run ends with.
inline std::string describe_link(const LinkStatus& link) {
    char text[256];
    if (link.state == LinkStatus::State::waiting)
        std::snprintf(text, sizeof text, "no messages yet");
    else
        std::snprintf(text, sizeof text, "%s (last state %.0f ms ago)", link_state_name(link.state), 1e3 * link.age_s);
    char counts[256];
    std::snprintf(counts, sizeof counts, ", %llu states, %llu meshes, %llu sessions, %llu rejected, %llu late, %llu commands sent",
                  static_cast<unsigned long long>(link.states), static_cast<unsigned long long>(link.meshes),
                  static_cast<unsigned long long>(link.sessions), static_cast<unsigned long long>(link.rejected),
                  static_cast<unsigned long long>(link.late), static_cast<unsigned long long>(link.commands_sent));
    return std::string(text) + counts;
}

// Where an obstacle's frame is now (ent_obstacle_pose): a retracted liver moves.
struct ObstaclePose {
    bool present = false;                      // false: removed (or unknown)
    double position_m[3] = {};
    double orientation_wxyz[4] = {1, 0, 0, 0};
};

// One frame's view of the scene, filled by Session::read on the render thread.
struct FrameState {
    double time_s = 0.0;                       // simulated time of the physics report
    ent_stats stats{};                         // of the snapshot read this frame
    ent_effect_stats effects[ENT_EFFECT_COUNT]{};
    std::vector<double> axis_xyz_m;            // evenly spaced in arc length
    std::vector<double> control_points_xyz_m;
    std::vector<double> spheres_xyz_m;         // the collision spheres' centres
    ent_mesh_view mesh{};                      // the skin; valid until the next read
    double skin_update_ms = 0.0;               // wall time of this frame's ent_skin_update
    std::uint32_t tool_count = 0;
    ToolReadback tools[kMaxTools];
    std::vector<ObstaclePose> obstacles;       // one per layout obstacle; empty: as the layout says
    bool paused = false;
    double gate_reached_s = -1.0;              // capture: the gate the physics waits at
    std::vector<StepSample> new_steps;         // every step since the last read, oldest first
    std::uint64_t dropped_steps = 0;           // steps the plots missed (the reader stalled)
    Problem problem;                           // the newest failure, if any
    LinkStatus link;                           // where the state comes from, if not from here
};

class Session {
public:
    virtual ~Session() = default;

    virtual std::string name() const = 0;            // for the title bar and the status line
    virtual const SceneLayout& layout() const = 0;
    // Changes when layout() does (a remote scene arrives after the session opens).
    virtual std::uint64_t layout_generation() const { return 0; }

    // Render thread, once a frame: the newest state and a fresh mesh.
    virtual void read(const FrameRequest& request, FrameState& frame) = 0;
    // Render thread: where the tools should go (newest wins).
    virtual void send(const ToolCommands& commands) = 0;

    // Controls of the simulation itself (a remote session would not have them all).
    virtual void set_paused(bool paused) = 0;
    virtual bool paused() const = 0;
    virtual void step_once() = 0;
    virtual void set_rate(double real_time_factor) = 0;
    virtual double rate() const = 0;
    virtual void set_step(double step_s) = 0;
    virtual double step() const = 0;
    // Back to the initial state; false with a message if the scene cannot be made again.
    virtual bool reset(std::string& error) = 0;
    // Frame-exact capture: the simulation never passes time_s (infinity: real time again);
    // at_gate says when it waits there (or has stopped on a failure).
    virtual void set_gate(double time_s) = 0;
    virtual bool at_gate(double time_s) = 0;

    // The skin: method and resolution. On failure the old skin stays and error says why.
    virtual bool set_skin(const ent_skin_desc& desc, std::string& error) = 0;
    virtual const ent_skin_desc& skin() const = 0;
    // The mesh's accuracy (costs more than an update; for a panel, not every frame).
    virtual bool skin_metrics(struct ent_skin_metrics& metrics) = 0;
};

}  // namespace viewer
