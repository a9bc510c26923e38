// SPDX-License-Identifier: Apache-2.0
// A scene simulated by enteron-lcm-server, seen over LCM (enteron-viewer --lcm URL): the
// Session the viewer draws, filled from the newest messages the RemoteLink's thread
// checked and handed over, and the tools the mouse drives sent back as tool_command_t.
// The render thread makes every call of this class; it never waits for the network.
//
// What a remote session cannot do, it says: the server owns the clock (no pause, step or
// slow motion: the controls do nothing), the skin (--mesh-skin), the step. Reset releases
// the tools (the viewer stops commanding them) and keeps watching. Headless captures run
// in wall time: frame k is drawn k / fps seconds after the first.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "../session.h"
#include "axis_tube.h"
#include "remote_link.h"

namespace viewer {

class RemoteSession final : public Session {
public:
    // A state older than this (wall time), or than three of the server's state periods if
    // longer, is stale: the server stopped or the network did.
    static constexpr double kStaleAfterS = 0.5;

    static std::unique_ptr<RemoteSession> open(const std::string& url, const std::string& channel_suffix,
                                               std::string& error);

    std::string name() const override { return name_; }
    const SceneLayout& layout() const override { return layout_; }
    std::uint64_t layout_generation() const override { return layout_generation_; }
    void read(const FrameRequest& request, FrameState& frame) override;
    void send(const ToolCommands& commands) override;
    void set_paused(bool) override {}
    bool paused() const override { return false; }
    void step_once() override {}
    void set_rate(double) override {}
    double rate() const override { return 1.0; }
    void set_step(double) override {}
    double step() const override { return scene_.tick_s; }
    bool reset(std::string& error) override;
    void set_gate(double) override {}
    bool at_gate(double time_s) override;
    bool set_skin(const ent_skin_desc& desc, std::string& error) override;
    const ent_skin_desc& skin() const override { return skin_; }
    bool skin_metrics(struct ent_skin_metrics&) override { return false; }

private:
    RemoteSession() = default;
    void take_messages(FrameState& frame);
    void fill_mesh(FrameState& frame);

    std::string name_, url_;
    std::unique_ptr<RemoteLink> link_;
    RemoteScene scene_;
    SceneLayout layout_;
    std::uint64_t layout_generation_ = 0;
    ent_skin_desc skin_{};
    RemoteState state_;
    RemoteMesh mesh_;
    bool have_state_ = false, have_mesh_ = false;
    MeshArrays tube_;
    std::int64_t tube_tick_ = -1;
    // Tools drive once the user has moved them: the commands when the scene arrived are
    // the baseline, and a tool whose target or jaws leave it is driven from then on.
    ToolCommands baseline_;
    bool baseline_set_ = false;
    RemoteCommands outgoing_;
    // Tool 0's applied tip when first seen, and how far the server has moved it since.
    bool tool0_seen_ = false;
    double tool0_start_m[3] = {};
    double tool0_largest_move_m_ = 0.0;
    std::string last_rejection_;
    std::chrono::steady_clock::time_point capture_start_{};
    bool capture_started_ = false;
};

}  // namespace viewer
