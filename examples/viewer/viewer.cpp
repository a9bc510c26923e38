// SPDX-License-Identifier: Apache-2.0
#include "viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <epoxy/gl.h>

#include <chrono>
#include <cstdio>
#include <limits>

#include "clock.h"
#include "demo_scene.h"
#include "script.h"
#ifdef ENTERON_VIEWER_WITH_LCM
#include "remote/remote_session.h"
#endif

namespace viewer {

namespace {

constexpr double kNoticeSeconds = 4.0;
// The laparoscope's tip inside the wall: 2 cm past the port, as a surgeon starts (the loops of a
// packed abdomen come within a few centimetres of the wall).
constexpr double kScopeInsertion_m = 0.02;

}  // namespace

Viewer::Viewer(const ViewerSettings& settings) : settings_(settings) {
    if (settings_.session.skin.struct_size == 0) ent_skin_desc_default(&settings_.session.skin);
}

Viewer::~Viewer() = default;

bool Viewer::open_initial(std::string& error) {
    if (!settings_.lcm_url.empty()) {
#ifdef ENTERON_VIEWER_WITH_LCM
        std::unique_ptr<Session> session = RemoteSession::open(settings_.lcm_url, settings_.lcm_channel_suffix, error);
#else
        std::unique_ptr<Session> session;
        error = "this enteron-viewer was built without LCM (liblcm-dev; ENTERON_WITH_LCM)";
#endif
        if (!session) {
            load_error_ = error;
            return false;
        }
        show(std::move(session), "", "");
        return true;
    }
    if (settings_.scene_path.empty())
        return open(demo_scene_json, "demo scene (built in)", "", error);
    std::string text;
    if (!read_text_file(settings_.scene_path, text, error)) {
        load_error_ = error;
        return false;
    }
    return open(text, settings_.scene_path, settings_.scene_path, error);
}

bool Viewer::open(const std::string& json, const std::string& name, const std::string& path, std::string& error) {
    // The skin method and resolution carry over from the scene shown before.
    if (session_) settings_.session.skin = session_->skin();
    LocalSessionOptions options = settings_.session;
    if (settings_.scene_motion) {
        const ScenePaths paths = scene_paths(demo_motion_for_scene(path.empty() ? nullptr : path.c_str()));
        options.tool0_path = settings_.scene_motion_tool ? paths.tool0 : ToolPathKeys();
        options.obstacle_paths = paths.obstacles;
    }
    // A mesh file is found next to the scene file, as ent_scene_create_json_file finds it.
    const std::size_t slash = path.rfind('/');
    const std::string scene_dir = slash == std::string::npos ? "" : path.substr(0, slash);
    std::unique_ptr<Session> session = LocalSession::open(json, name, scene_dir, options, error);
    if (!session) {
        load_error_ = error;
        json_edit_ = json;  // to mend it in the Scene panel
        return false;
    }
    settings_.session = options;  // the paths the scene shown plays
    show(std::move(session), json, path);
    return true;
}

void Viewer::show(std::unique_ptr<Session> session, const std::string& json, const std::string& path) {
    frame_ = FrameState();  // its mesh view points into the old skin
    session_ = std::move(session);
    scene_path_ = path;
    load_error_.clear();
    json_edit_ = json;
    tools_.reset(session_->layout());
    layout_generation_ = session_->layout_generation();
    histories_.clear();
    camera_framed_ = false;
    clock_started_ = false;
}

void Viewer::start_clock() {
    if (!session_ || clock_started_) return;
    session_->set_gate(std::numeric_limits<double>::infinity());
    clock_started_ = true;
}

void Viewer::open_file(const std::string& path) {
    std::string text, error;
    if (!read_text_file(path, text, error) || !open(text, path, path, error)) {
        load_error_ = error;
        std::fprintf(stderr, "enteron-viewer: %s\n", error.c_str());
        return;
    }
    notify("opened " + path);
}

bool Viewer::init_renderer(std::string& error) {
    renderer_ = std::make_unique<Renderer>();
    if (renderer_->init(error)) return true;
    renderer_.reset();
    return false;
}

void Viewer::set_window_size(int width, int height) {
    window_width_ = std::max(1, width);
    window_height_ = std::max(1, height);
}

void Viewer::notify(const std::string& message) {
    notice_ = message;
    notice_until_s_ = wall_seconds() + kNoticeSeconds;
}

std::string Viewer::take_screenshot_request() {
    std::string path;
    path.swap(screenshot_request_);
    return path;
}

void Viewer::frame_camera() {
    if (!session_) return;
    // The cavity's lower two thirds if there is a cavity (the bowel lies on its floor), else
    // the bowel as it is now.
    const SceneLayout& layout = session_->layout();
    Eigen::AlignedBox3d box;
    if (layout.scene_size_m > 0.0) {
        const Eigen::Vector3d centre(layout.scene_center_m[0], layout.scene_center_m[1], layout.scene_center_m[2]);
        const double half = 0.5 * layout.scene_size_m;
        box.extend(centre - Eigen::Vector3d::Constant(half));
        box.extend(centre + Eigen::Vector3d(half, half, half / 3.0));
    } else {
        box = mesh_bounds(frame_.mesh);
    }
    if (box.isEmpty()) return;  // nothing yet: frame it on the next frame
    camera_.frame(box.center(), box.sizes().maxCoeff());
    camera_framed_ = true;
    if (settings_.laparoscope) look_through_scope();
}

void Viewer::look_through_scope() {
    if (!session_) return;
    const SceneLayout& layout = session_->layout();
    const Eigen::AlignedBox3d bowel = mesh_bounds(frame_.mesh);
    const Eigen::Vector3d target = bowel.isEmpty() ? camera_.target() : bowel.center();
    // The umbilical port: the cavity's top above its centre; without a cavity, 20 cm above the bowel.
    const Eigen::Vector3d port = layout.port_known ? Eigen::Vector3d(layout.port_m[0], layout.port_m[1], layout.port_m[2])
                                                   : Eigen::Vector3d(target + Eigen::Vector3d(0.0, 0.0, 0.2));
    camera_.look_through_scope(port, target, kScopeInsertion_m);
}

void Viewer::update() {
    if (!session_) return;
    FrameRequest request;
    request.axis = toggles_.axis;
    request.control_points = toggles_.control_points || (toggles_.mesentery && session_->layout().mesentery);
    request.spheres = toggles_.spheres;
    const std::uint64_t failures_before = frame_.problem.count;
    session_->read(request, frame_);
    if (session_->layout_generation() != layout_generation_) {  // a remote scene arrived: its tools, its view
        layout_generation_ = session_->layout_generation();
        tools_.reset(session_->layout());
        camera_framed_ = false;
    }
    if (frame_.problem.count != failures_before) {  // shown on the status line; the terminal gets it too
        const Problem& p = frame_.problem;
        std::fprintf(stderr, "enteron-viewer: %s from %s at t = %.3f s: %s\n", status_name(p.status), p.call.c_str(),
                     p.time_s, p.message.c_str());
    }
    // A tool on a scripted path is where the path put it: no target of the mouse's to show.
    if (!settings_.session.tool0_path.empty() && frame_.tool_count > 0) tools_.commands().target[0] = frame_.tools[0].pose;
    histories_.plotted_tool = tools_.active();
    histories_.add(frame_);
    session_->send(tools_.commands());
    if (!camera_framed_) frame_camera();
}

void Viewer::render(int framebuffer_width, int framebuffer_height) {
    glViewport(0, 0, framebuffer_width, framebuffer_height);
    if (!session_ || !renderer_) {
        glClearColor(0.12f, 0.12f, 0.14f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return;
    }
    SceneView view;
    view.layout = &session_->layout();
    view.frame = &frame_;
    view.targets = &tools_.commands();
    view.toggles = toggles_;
    view.force_scale_m_per_N = force_scale_m_per_N_;
    renderer_->draw(view, camera_, framebuffer_width, framebuffer_height);
}

// ---- input ----------------------------------------------------------------------------

void Viewer::mouse_button(int button, bool pressed, int mods, double x, double y) {
    mouse_x_ = x;
    mouse_y_ = y;
    switch (button) {
        case GLFW_MOUSE_BUTTON_LEFT:  // the tool
            if (pressed)
                tools_.begin_drag(camera_, camera_.ray(x, y, window_width_, window_height_));
            else
                tools_.end_drag();
            break;
        case GLFW_MOUSE_BUTTON_RIGHT:  // orbit; with Shift, pan
            orbiting_ = pressed && (mods & GLFW_MOD_SHIFT) == 0;
            panning_ = pressed && (mods & GLFW_MOD_SHIFT) != 0;
            break;
        case GLFW_MOUSE_BUTTON_MIDDLE:  // pan
            panning_ = pressed;
            break;
        default:
            break;
    }
}

void Viewer::mouse_move(double x, double y) {
    const double dx = x - mouse_x_, dy = y - mouse_y_;
    mouse_x_ = x;
    mouse_y_ = y;
    if (orbiting_) camera_.orbit(dx, dy);
    if (panning_) camera_.pan(dx, dy, window_height_);
    if (tools_.dragging()) tools_.drag(camera_.ray(x, y, window_width_, window_height_));
}

void Viewer::scroll(double notches, int mods) {
    if ((mods & (GLFW_MOD_CONTROL | GLFW_MOD_SHIFT)) != 0)
        camera_.zoom(notches);
    else
        tools_.push(camera_, notches);  // wheel forward: the tool goes deeper
}

void Viewer::reset() {
    if (!session_) return;
    std::string error;
    if (!session_->reset(error)) {
        // The scene was accepted once, so only memory can fail here; say so and stay empty.
        load_error_ = error;
        session_.reset();
        return;
    }
    frame_ = FrameState();
    tools_.reset(session_->layout());
    histories_.clear();
    clock_started_ = false;  // it starts again held at its opening gate
    notify("reset");
}

void Viewer::set_skin(const ent_skin_desc& desc) {
    std::string error;
    if (!session_ || !session_->set_skin(desc, error)) {
        if (!error.empty()) notify(error);
        return;
    }
    frame_.mesh = ent_mesh_view{};  // pointed into the old skin
    metrics_valid_ = false;
}

void Viewer::key(int key, int mods) {
    const bool control = (mods & GLFW_MOD_CONTROL) != 0;
    if (control && key == GLFW_KEY_Q) quit_ = true;
    if (control && key == GLFW_KEY_L && !scene_path_.empty()) open_file(scene_path_);
    if (control) return;
    switch (key) {
        case GLFW_KEY_F1: show_help_ = !show_help_; break;
        case GLFW_KEY_H: settings_.ui = settings_.ui == UiMode::full ? UiMode::none : UiMode::full; break;
        case GLFW_KEY_P: screenshot_request_ = "enteron-viewer.png"; break;
        case GLFW_KEY_HOME: frame_camera(); break;
        case GLFW_KEY_V:  // the laparoscope, or back to the orbit camera where it was
            settings_.laparoscope = !settings_.laparoscope;
            if (settings_.laparoscope)
                look_through_scope();
            else
                camera_.leave_scope();
            break;
        case GLFW_KEY_W: toggles_.wireframe = !toggles_.wireframe; break;
        case GLFW_KEY_A: toggles_.axis = !toggles_.axis; break;
        case GLFW_KEY_C: toggles_.control_points = !toggles_.control_points; break;
        case GLFW_KEY_S: toggles_.spheres = !toggles_.spheres; break;
        case GLFW_KEY_M: toggles_.mesentery = !toggles_.mesentery; break;
        case GLFW_KEY_O: toggles_.obstacles = !toggles_.obstacles; break;
        case GLFW_KEY_F: toggles_.force_arrows = !toggles_.force_arrows; break;
        case GLFW_KEY_K: toggles_.skin = !toggles_.skin; break;
        case GLFW_KEY_L: toggles_.shadows = !toggles_.shadows; break;
        case GLFW_KEY_1:
        case GLFW_KEY_2:
        case GLFW_KEY_3:  // tube, point_skeleton, convolution: the same resolution, another method
            if (session_) {
                ent_skin_desc desc = session_->skin();
                desc.method = key == GLFW_KEY_1 ? ENT_SKIN_TUBE : key == GLFW_KEY_2 ? ENT_SKIN_POINT_SKELETON : ENT_SKIN_CONVOLUTION;
                set_skin(desc);
            }
            break;
        case GLFW_KEY_G: tools_.toggle_grasp(); break;
        case GLFW_KEY_TAB: tools_.set_active(tools_.count() == 0 ? 0 : (tools_.active() + 1) % tools_.count()); break;
        default: break;
    }
    if (!session_) return;
    switch (key) {
        case GLFW_KEY_SPACE: session_->set_paused(!session_->paused()); break;
        case GLFW_KEY_RIGHT:  // one step, pausing first
            session_->set_paused(true);
            session_->step_once();
            break;
        case GLFW_KEY_BACKSPACE: reset(); break;
        case GLFW_KEY_LEFT_BRACKET: session_->set_rate(std::max(1.0 / 64.0, 0.5 * session_->rate())); break;
        case GLFW_KEY_RIGHT_BRACKET: session_->set_rate(std::min(1.0, 2.0 * session_->rate())); break;
        default: break;
    }
}

}  // namespace viewer
