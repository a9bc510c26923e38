// SPDX-License-Identifier: Apache-2.0
// The viewer in a window: GLFW 3 for the window and the input, the frame drawn into a
// Canvas and shown; the physics runs on its own thread in real time meanwhile.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <epoxy/gl.h>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include "run.h"

namespace viewer {

namespace {

using Clock = std::chrono::steady_clock;

// Frames faster than this wait: without a vertical sync (Xvfb, some drivers) the render
// thread would otherwise spin and take the core the physics thread needs.
constexpr double kMaxFramesPerSecond = 60.0;

Viewer* viewer_of(GLFWwindow* window) { return static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

// The scene gets the mouse and the keys only when the panels do not want them.
void on_mouse_button(GLFWwindow* window, int button, int action, int mods) {
    if (ImGui::GetIO().WantCaptureMouse && action == GLFW_PRESS) return;
    double x, y;
    glfwGetCursorPos(window, &x, &y);
    viewer_of(window)->mouse_button(button, action == GLFW_PRESS, mods, x, y);
}

void on_cursor(GLFWwindow* window, double x, double y) { viewer_of(window)->mouse_move(x, y); }

void on_scroll(GLFWwindow* window, double, double dy) {
    if (ImGui::GetIO().WantCaptureMouse) return;
    int mods = 0;
    if (glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS)
        mods |= GLFW_MOD_CONTROL;
    if (glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS)
        mods |= GLFW_MOD_SHIFT;
    viewer_of(window)->scroll(dy, mods);
}

void on_key(GLFWwindow* window, int key, int, int action, int mods) {
    if (ImGui::GetIO().WantCaptureKeyboard || (action != GLFW_PRESS && action != GLFW_REPEAT)) return;
    viewer_of(window)->key(key, mods);
}

void on_drop(GLFWwindow* window, int count, const char** paths) {
    if (count > 0) viewer_of(window)->open_file(paths[count - 1]);
}

void on_glfw_error(int code, const char* description) {
    std::fprintf(stderr, "enteron-viewer: GLFW error %d: %s\n", code, description);
}

int run_frames(GLFWwindow* window, Viewer& viewer, RunOptions& options);

}  // namespace

int run_window(Viewer& viewer, RunOptions& options) {
    glfwSetErrorCallback(on_glfw_error);
    if (glfwInit() != GLFW_TRUE) {
        std::fprintf(stderr, "enteron-viewer: no window: GLFW cannot start (no display? try --headless, or xvfb-run)\n");
        return kExitNoRenderer;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    const std::string title = "Enteron viewer - " + (viewer.session() ? viewer.session()->name() : std::string("no scene"));
    GLFWwindow* window = glfwCreateWindow(options.width, options.height, title.c_str(), nullptr, nullptr);
    if (window == nullptr) {
        std::fprintf(stderr, "enteron-viewer: no window: cannot make an OpenGL 3.3 core context\n");
        glfwTerminate();
        return kExitNoRenderer;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window, &viewer);
    glfwSetMouseButtonCallback(window, on_mouse_button);
    glfwSetCursorPosCallback(window, on_cursor);
    glfwSetScrollCallback(window, on_scroll);
    glfwSetKeyCallback(window, on_key);
    glfwSetDropCallback(window, on_drop);
    create_imgui();
    ImGui_ImplGlfw_InitForOpenGL(window, /*install_callbacks=*/true);  // chains to ours
    ImGui_ImplOpenGL3_Init("#version 330");

    const int status = run_frames(window, viewer, options);
    viewer.release_renderer();  // its GL objects go with the context
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}

namespace {

int run_frames(GLFWwindow* window, Viewer& viewer, RunOptions& options) {
    int status = kExitOk;
    std::string error;
    Canvas canvas;
    FrameOutputs outputs;
    bool outputs_open = false;  // at the first frame, at the framebuffer's size
    if (!viewer.init_renderer(error)) {
        std::fprintf(stderr, "enteron-viewer: no renderer: %s\n", error.c_str());
        status = kExitNoRenderer;
    }
    const int samples = default_samples();
    const auto start = Clock::now();
    auto last_frame = start;
    const double end_s = options.start_s + options.seconds;
    while (status == kExitOk && !glfwWindowShouldClose(window) && !viewer.quit_requested()) {
        glfwPollEvents();
        int window_width, window_height, width, height;
        glfwGetWindowSize(window, &window_width, &window_height);
        glfwGetFramebufferSize(window, &width, &height);
        if (width <= 0 || height <= 0) {  // minimised
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            continue;
        }
        viewer.set_window_size(window_width, window_height);
        viewer.update();
        // The script's events up to this frame's time; its screenshots show this frame. The
        // script and --seconds count simulated time; with no scene here (none loaded, or a
        // remote one, whose clock is the server's), wall time.
        const bool wall_clock = viewer.session() == nullptr || viewer.frame().link.remote;
        std::vector<std::string> screenshots;
        options.script.play(wall_clock ? std::chrono::duration<double>(Clock::now() - start).count() : viewer.frame().time_s,
                            viewer, screenshots);
        if (!canvas.resize(width, height, samples, error)) {
            std::fprintf(stderr, "enteron-viewer: %s\n", error.c_str());
            status = kExitNoRenderer;
            break;
        }
        ImGui_ImplGlfw_NewFrame();
        draw_frame(viewer, canvas);
        const std::string asked = viewer.take_screenshot_request();
        if (!asked.empty()) {
            screenshots.push_back(asked);
            viewer.notify("screenshot: " + asked);
        }
        if (!outputs_open && !outputs.open(options, canvas.width(), canvas.height(), error)) {
            std::fprintf(stderr, "enteron-viewer: %s\n", error.c_str());
            status = kExitFailed;
            break;
        }
        outputs_open = true;
        if (!outputs.add(canvas, screenshots, error)) {
            std::fprintf(stderr, "enteron-viewer: %s\n", error.c_str());
            status = kExitFailed;
        }
        canvas.present(width, height);
        glfwSwapBuffers(window);
        viewer.start_clock();
        const auto next = last_frame + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / kMaxFramesPerSecond));
        std::this_thread::sleep_until(next);
        last_frame = Clock::now();
        const double wall_s = std::chrono::duration<double>(Clock::now() - start).count();
        if (options.seconds > 0.0 && !wall_clock && viewer.frame().time_s >= end_s - 1e-9) break;
        if (options.seconds > 0.0 && wall_clock && wall_s >= options.seconds) break;
    }
    if (status == kExitOk && !outputs.finish(error)) {
        std::fprintf(stderr, "enteron-viewer: %s\n", error.c_str());
        status = kExitFailed;
    }
    print_summary(viewer, outputs.frames(), std::chrono::duration<double>(Clock::now() - start).count());
    return status;
}

}  // namespace

}  // namespace viewer
