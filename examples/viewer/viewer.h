// SPDX-License-Identifier: Apache-2.0
// The viewer itself, apart from where its pixels go (a window, or offscreen for
// --headless): the session it shows, the camera, the mouse-driven tools, what is drawn,
// the plots and the panels. Everything here runs on the render thread; the physics runs
// on the session's own thread.
#pragma once

#include <memory>
#include <string>

#include "camera.h"
#include "histories.h"
#include "local_session.h"
#include "renderer.h"
#include "session.h"
#include "tool_control.h"

namespace viewer {

enum class UiMode {
    full,  // every panel and the status line
    hud,   // time, force and the force plot in a corner; the status line on an error
    none,  // the picture alone
};

struct ViewerSettings {
    LocalSessionOptions session;   // how scenes are opened
    std::string scene_path;        // empty: the built-in demo scene
    std::string lcm_url;           // not empty: show enteron-lcm-server's session there instead
    std::string lcm_channel_suffix;
    UiMode ui = UiMode::full;
    // No script given: each scene opened plays its own motion (demo_scene.h: the demo
    // scene's tool path, the abdomen's retractor and grasper), the tool's part only if
    // scene_motion_tool (headless; in a window the mouse is the tool).
    bool scene_motion = false;
    bool scene_motion_tool = false;
    // Look through the laparoscope from the start (key V switches).
    bool laparoscope = false;
};

class Viewer {
public:
    explicit Viewer(const ViewerSettings& settings);
    ~Viewer();

    // Opens the scene file (or the demo). On failure the viewer still runs, empty, with
    // the error (naming the bad key) on its status line; error gets it too.
    bool open_initial(std::string& error);
    // Needs a current OpenGL 3.3 context; release_renderer before that context goes.
    bool init_renderer(std::string& error);
    void release_renderer() { renderer_.reset(); }

    // Input, in window pixels from the top left (GLFW's, or a script's).
    void set_window_size(int width, int height);
    void mouse_button(int button, bool pressed, int mods, double x, double y);
    void mouse_move(double x, double y);
    void scroll(double notches, int mods);
    void key(int key, int mods);
    void open_file(const std::string& path);  // a file dropped on the window

    // Once a frame: read the session, feed the plots, send the tools' targets.
    void update();
    // The scene, into the current framebuffer.
    void render(int framebuffer_width, int framebuffer_height);
    // The panels (between ImGui::NewFrame and ImGui::Render).
    void build_ui();
    // A window calls this once its first frame of a scene is on screen: a scene opened held
    // at t = 0 (ViewerSettings.session.gate_s = 0) then starts, so that the simulation
    // starts with the picture and not with the slower start of the window.
    void start_clock();

    Session* session() { return session_.get(); }
    const Session* session() const { return session_.get(); }
    const FrameState& frame() const { return frame_; }
    const Histories& histories() const { return histories_; }
    bool quit_requested() const { return quit_; }
    // A screenshot the user asked for (key P): the path, once, then "".
    std::string take_screenshot_request();
    // A line for the status bar that goes away by itself.
    void notify(const std::string& message);

private:
    bool open(const std::string& json, const std::string& name, const std::string& path, std::string& error);
    void show(std::unique_ptr<Session> session, const std::string& json, const std::string& path);
    void reset();
    void set_skin(const ent_skin_desc& desc);
    void frame_camera();
    // The laparoscope through the umbilical port (the cavity's top above its centre),
    // looking at the bowel (docs/viewer.md).
    void look_through_scope();
    void build_panels();
    void build_hud();
    void build_status_line(bool always);
    void build_help();

    ViewerSettings settings_;
    std::unique_ptr<Session> session_;
    std::string scene_path_;          // the file shown, "" for the demo
    std::string load_error_;          // why the last open failed
    std::string json_edit_;           // the scene panel's editor
    Camera camera_;
    bool camera_framed_ = false;
    std::uint64_t layout_generation_ = 0;
    bool clock_started_ = false;
    ToolControl tools_;
    DrawToggles toggles_;
    double force_scale_m_per_N_ = 0.02;
    std::unique_ptr<Renderer> renderer_;
    FrameState frame_;
    Histories histories_;
    int window_width_ = 1, window_height_ = 1;
    double mouse_x_ = 0.0, mouse_y_ = 0.0;
    bool orbiting_ = false, panning_ = false;
    bool quit_ = false, show_help_ = false;
    std::string screenshot_request_;
    std::string notice_;
    double notice_until_s_ = 0.0;     // wall clock
    struct ent_skin_metrics metrics_{};
    bool metrics_valid_ = false;
    double metrics_wall_s_ = -1.0;
};

}  // namespace viewer
