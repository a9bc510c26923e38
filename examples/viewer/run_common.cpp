// SPDX-License-Identifier: Apache-2.0
#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "run.h"

namespace viewer {

void create_imgui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini left in the user's directory
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4.0f;
    ImGui::GetStyle().FrameRounding = 3.0f;
    static const char* const kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // fonts-dejavu-core
    struct stat file;
    if (stat(kFont, &file) == 0 && io.Fonts->AddFontFromFileTTF(kFont, 15.0f) != nullptr) return;
    io.Fonts->AddFontDefault();
}

void draw_frame(Viewer& viewer, const Canvas& canvas) {
    canvas.bind();
    viewer.render(canvas.width(), canvas.height());
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    viewer.build_ui();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    canvas.resolve();
}

bool FrameOutputs::open(const RunOptions& options, int width, int height, std::string& error) {
    options_ = options;
    width_ = width;
    height_ = height;
    if (!options_.frames_dir.empty() && mkdir(options_.frames_dir.c_str(), 0777) != 0 && errno != EEXIST) {
        error = "cannot make " + options_.frames_dir + ": " + std::strerror(errno);
        return false;
    }
    return options_.video_path.empty() || video_.open(options_.video_path, width, height, options_.fps, error);
}

bool FrameOutputs::add(const Canvas& canvas, const std::vector<std::string>& screenshots, std::string& error) {
    ++frames_;
    if (!wanted() && screenshots.empty()) return true;
    if (canvas.width() != width_ || canvas.height() != height_) {
        error = "the window changed size while its frames were being recorded";
        return false;
    }
    canvas.read_rgb(rgb_);
    if (!options_.frames_dir.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "/frame_%05d.png", frames_);
        if (!write_png(options_.frames_dir + name, width_, height_, rgb_, error)) return false;
    }
    if (video_.is_open() && !video_.write(rgb_, error)) return false;
    for (const std::string& path : screenshots) {
        if (!write_png(path, width_, height_, rgb_, error)) return false;
        std::printf("enteron-viewer: wrote %s\n", path.c_str());
    }
    return true;
}

bool FrameOutputs::finish(std::string& error) {
    if (!options_.screenshot_path.empty() && !rgb_.empty()) {
        if (!write_png(options_.screenshot_path, width_, height_, rgb_, error)) return false;
        std::printf("enteron-viewer: wrote %s (the last frame)\n", options_.screenshot_path.c_str());
    }
    if (video_.is_open()) {
        if (!video_.close(error)) return false;
        std::printf("enteron-viewer: wrote %s (%d frames at %g frames/s)\n", options_.video_path.c_str(), frames_,
                    options_.fps);
    }
    if (!options_.frames_dir.empty())
        std::printf("enteron-viewer: wrote %d frames to %s\n", frames_, options_.frames_dir.c_str());
    return true;
}

void print_summary(const Viewer& viewer, int frames, double wall_s) {
    const Histories& h = viewer.histories();
    const FrameState& frame = viewer.frame();
    std::printf("enteron-viewer: %d frames in %.1f s of wall time (%.1f frames/s); simulated t = %.3f s", frames,
                wall_s, wall_s > 0.0 ? frames / wall_s : 0.0, frame.time_s);
    if (const Session* session = viewer.session()) {
        const int method = session->skin().method;
        std::printf("; step median %.0f us, largest %.0f us; skin %s, %u triangles, update %.2f ms", h.step_median_us,
                    h.step_max_us, skin_method_name(method), frame.mesh.triangle_count,
                    h.skin_update_ms);
    }
    std::printf("\nenteron-viewer: force plot: %llu samples, %llu non-zero, largest |F| %.3f N",
                static_cast<unsigned long long>(h.samples), static_cast<unsigned long long>(h.nonzero_samples),
                h.largest_force_N);
    if (h.first_contact_time_s >= 0.0) std::printf(", first contact at t = %.3f s", h.first_contact_time_s);
    if (frame.tool_count > 0) {
        const double* p = frame.tools[0].pose.position_m;
        std::printf("; tool 0 tip at (%.4f, %.4f, %.4f) m", p[0], p[1], p[2]);
    }
    if (frame.link.remote) {
        const LinkStatus& link = frame.link;
        std::printf("\nenteron-viewer: remote %s: %s; tool 0 moved %.4f m, sent (%.6f, %.6f, %.6f) m, the server's "
                    "command (%.6f, %.6f, %.6f) m",
                    link.url.c_str(), describe_link(link).c_str(), link.tool0_largest_move_m, link.tool0_sent_m[0],
                    link.tool0_sent_m[1], link.tool0_sent_m[2], link.tool0_commanded_m[0], link.tool0_commanded_m[1],
                    link.tool0_commanded_m[2]);
        std::printf("; tool 0 status: %s", link.tool_status[0].empty() ? "ok" : link.tool_status[0].c_str());
    }
    std::printf("\nenteron-viewer: %llu failed calls\n", static_cast<unsigned long long>(frame.problem.count));
    std::fflush(stdout);
}

}  // namespace viewer
