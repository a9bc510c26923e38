// SPDX-License-Identifier: Apache-2.0
// A scene simulated in this process: the library, a physics thread that alone steps the
// scene, and a skin that the render thread alone updates from the published snapshot.
// The render thread makes every call of this class.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "physics_thread.h"
#include "session.h"

namespace viewer {

struct LocalSessionOptions {
    ent_skin_desc skin{};       // struct_size 0: ent_skin_desc_default
    double step_s = 0.0;        // 0: the scene's solver timestep
    double rate = 1.0;
    bool paused = false;
    double gate_s = std::numeric_limits<double>::infinity();
    ToolPathKeys tool0_path;    // a scripted path for tool 0 (empty: the mouse drives it)
    std::vector<ObstaclePath> obstacle_paths;  // scripted organs (a retractor)
};

class LocalSession final : public Session {
public:
    // Creates the scene from JSON text and starts it; a mesh obstacle's relative "file" is
    // found in scene_dir (the scene file's directory; "": the current one). Null, with the
    // library's message (naming the bad key) in error, if the library refuses the description.
    static std::unique_ptr<LocalSession> open(const std::string& json, const std::string& name,
                                              const std::string& scene_dir, const LocalSessionOptions& options,
                                              std::string& error);
    ~LocalSession() override;

    std::string name() const override { return name_; }
    const SceneLayout& layout() const override { return layout_; }
    void read(const FrameRequest& request, FrameState& frame) override;
    void send(const ToolCommands& commands) override;
    void set_paused(bool paused) override { physics_->set_paused(paused); }
    bool paused() const override { return physics_->paused(); }
    void step_once() override { physics_->step_once(); }
    void set_rate(double rate) override { physics_->set_rate(rate); }
    double rate() const override { return physics_->rate(); }
    void set_step(double step_s) override { physics_->set_step(step_s); }
    double step() const override { return physics_->step(); }
    bool reset(std::string& error) override;
    void set_gate(double time_s) override { physics_->set_gate(time_s); }
    bool at_gate(double time_s) override;
    bool set_skin(const ent_skin_desc& desc, std::string& error) override;
    const ent_skin_desc& skin() const override { return options_.skin; }
    bool skin_metrics(struct ent_skin_metrics& metrics) override;

private:
    LocalSession() = default;
    bool start(std::string& error);  // scene, skin, physics thread
    bool read_meshes(std::string& error);  // the mesh obstacles' triangles, before the physics thread
    void stop();                     // the reverse
    void record(const char* call, ent_status status);  // a failure on the render thread

    std::string json_, name_, scene_dir_;
    LocalSessionOptions options_;
    SceneLayout layout_;
    ent_scene* scene_ = nullptr;
    ent_skin* skin_ = nullptr;                 // render thread only
    std::unique_ptr<PhysicsThread> physics_;
    PhysicsReport report_;                     // the newest the physics thread published
    std::uint64_t physics_failures_seen_ = 0;  // of report_.failures, already in problem_
    bool jaws_closed_[kMaxTools] = {};         // the grasp level last posted
    Problem problem_;                          // the newest failure, of either thread
};

// The scene file's text, or false with a message naming the file.
bool read_text_file(const std::string& path, std::string& text, std::string& error);

}  // namespace viewer
