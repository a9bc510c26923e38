// SPDX-License-Identifier: Apache-2.0
// The viewer without a display (--headless): an OpenGL 3.3 core context from EGL on Mesa's
// surfaceless platform (examples/egl_offscreen_context.h; software rendering with llvmpipe:
// no X server, no GPU), frames drawn into a Canvas at a fixed rate in simulated time. The
// physics thread still runs on its own, up to a gate the render thread moves one frame at a
// time, so every frame shows exactly the simulated time it is stamped with, however slow
// the rendering.
#include <epoxy/gl.h>

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "egl_offscreen_context.h"
#include "run.h"

namespace viewer {

namespace {

using Clock = std::chrono::steady_clock;

// Longer than this without reaching a frame's time means the physics thread is stuck.
constexpr double kFrameTimeoutS = 60.0;

int capture(Viewer& viewer, RunOptions& options) {
    std::string error;
    Canvas canvas;
    FrameOutputs outputs;
    // Pictures are made once and kept: multisampled even on a software renderer.
    if (!viewer.init_renderer(error) || !canvas.resize(options.width, options.height, 4, error)) {
        std::fprintf(stderr, "enteron-viewer: no renderer: %s\n", error.c_str());
        return kExitNoRenderer;
    }
    if (!outputs.open(options, options.width, options.height, error)) {
        std::fprintf(stderr, "enteron-viewer: %s\n", error.c_str());
        return kExitFailed;
    }
    Session& session = *viewer.session();
    viewer.set_window_size(options.width, options.height);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(options.width), static_cast<float>(options.height));
    io.DeltaTime = static_cast<float>(1.0 / options.fps);
    // The text keeps its share of the picture (fonts are made for 720 lines), down to a size
    // still legible.
    io.FontGlobalScale = std::clamp(static_cast<float>(options.height) / 720.0f, 0.75f, 2.0f);

    // Dear ImGui sizes a new auto-sized window on its first frame and shows it from the
    // second: that first frame is made here, not captured.
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    viewer.build_ui();
    ImGui::EndFrame();

    const auto start = Clock::now();
    const long frames = std::max(1L, std::lround(options.seconds * options.fps));
    auto frame_time = [&options](long k) { return options.start_s + static_cast<double>(k) / options.fps; };
    int status = kExitOk;
    for (long k = 1; k <= frames && status == kExitOk; ++k) {
        const double time_s = frame_time(k);
        session.set_gate(time_s);
        const auto waiting = Clock::now();
        while (!session.at_gate(time_s)) {
            if (std::chrono::duration<double>(Clock::now() - waiting).count() > kFrameTimeoutS) {
                std::fprintf(stderr, "enteron-viewer: the simulation did not reach t = %.3f s in %.0f s\n", time_s,
                             kFrameTimeoutS);
                return kExitFailed;
            }
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
        std::vector<std::string> screenshots;
        options.script.play(time_s, viewer, screenshots);
        viewer.update();  // the snapshot at exactly time_s: the skin, the stats, the tools
        // The physics goes on to the next frame's time while this one is drawn and saved.
        if (k < frames) session.set_gate(frame_time(k + 1));
        draw_frame(viewer, canvas);
        if (!outputs.add(canvas, screenshots, error)) {
            std::fprintf(stderr, "enteron-viewer: %s\n", error.c_str());
            status = kExitFailed;
        }
        if (viewer.frame().problem.count > 0) status = kExitFailed;  // reported by Viewer::update
    }
    const LinkStatus& link = viewer.frame().link;
    if (link.remote && link.states == 0) {  // a capture of nothing: say why
        std::fprintf(stderr, "enteron-viewer: no scene_state_t arrived from %s in %.1f s (is enteron-lcm-server running "
                             "there, with the same --channel-suffix and a --state-hz above 0?)\n",
                     link.url.c_str(), options.seconds);
        status = kExitFailed;
    }
    if (!outputs.finish(error)) {
        std::fprintf(stderr, "enteron-viewer: %s\n", error.c_str());
        status = kExitFailed;
    }
    print_summary(viewer, outputs.frames(), std::chrono::duration<double>(Clock::now() - start).count());
    return status;
}

}  // namespace

int run_headless(Viewer& viewer, RunOptions& options) {
    enteron_examples::EglOffscreenContext context;
    std::string error;
    if (!context.create(error)) {
        std::fprintf(stderr,
                     "enteron-viewer: no renderer: %s; or run the viewer in a window, under xvfb-run if there "
                     "is no display\n",
                     error.c_str());
        return kExitNoRenderer;
    }
    std::printf("enteron-viewer: headless, OpenGL on %s\n", context.renderer().c_str());
    create_imgui();
    ImGui_ImplOpenGL3_Init("#version 330");
    const int status = capture(viewer, options);
    viewer.release_renderer();  // its GL objects go with the context
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
    return status;
}

}  // namespace viewer
