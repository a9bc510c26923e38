// SPDX-License-Identifier: Apache-2.0
// The two ways the viewer runs: in a window (GLFW), in real time; or --headless, offscreen
// (EGL), frame-exact at a fixed rate in simulated time. Both draw into a Canvas and can
// write the frames, a video and screenshots (FrameOutputs).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "canvas.h"
#include "script.h"
#include "viewer.h"

namespace viewer {

// Exit statuses of enteron-viewer.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;       // the scene did not load, a library call failed, an output failed
inline constexpr int kExitUsage = 2;        // a bad command line
inline constexpr int kExitNoRenderer = 3;   // no OpenGL 3.3 context could be made

struct RunOptions {
    double seconds = 0.0;          // simulated seconds to run (0: until the window closes)
    double start_s = 0.0;          // headless: simulated first, not captured
    double fps = 30.0;             // headless: frames per simulated second
    int width = 1600, height = 900; // the window's; --headless makes 1280 x 720 unless told
    std::string frames_dir;        // every frame as a PNG
    std::string video_path;        // .mp4 or .gif
    std::string screenshot_path;   // the last frame as a PNG
    Script script;
};

// Writes what a run asked for, frame by frame.
class FrameOutputs {
public:
    bool open(const RunOptions& options, int width, int height, std::string& error);
    bool wanted() const { return !options_.frames_dir.empty() || video_.is_open() || !options_.screenshot_path.empty(); }
    // This frame (resolved on the canvas) to the frames directory, the video, and the
    // screenshots due now (the script's and the user's).
    bool add(const Canvas& canvas, const std::vector<std::string>& screenshots, std::string& error);
    // The last frame as --screenshot, and the video closed.
    bool finish(std::string& error);
    int frames() const { return frames_; }

private:
    RunOptions options_;
    VideoEncoder video_;
    std::vector<unsigned char> rgb_;
    int width_ = 0, height_ = 0, frames_ = 0;
};

// Dear ImGui's context, style and font (DejaVu Sans when installed), for either run.
void create_imgui();
// One frame into the canvas: the scene, then the panels (after the platform's NewFrame).
void draw_frame(Viewer& viewer, const Canvas& canvas);

int run_window(Viewer& viewer, RunOptions& options);
int run_headless(Viewer& viewer, RunOptions& options);

// The line a run ends with: what was shown, for people and for the tests.
void print_summary(const Viewer& viewer, int frames, double wall_s);

}  // namespace viewer
