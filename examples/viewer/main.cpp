// SPDX-License-Identifier: Apache-2.0
// enteron-viewer: see the bowel move and push it with the mouse (docs/viewer.md).
//
//   enteron-viewer [SCENE.json] [options]      with no scene: the demo scene
//
// It uses only the public C API of libenteron: a physics thread drives the scene, the
// render thread draws the published snapshot through a skin (physics_thread.h). With
// --lcm URL it shows an enteron-lcm-server's session instead (remote/remote_session.h).
#include <enteron/enteron.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "run.h"
#include "viewer.h"

namespace {

const char kUsage[] =
    "usage: enteron-viewer [SCENE.json] [options]\n"
    "  With no scene, the demo scene: a 6 m small bowel in the abdominal cavity, and a tool.\n"
    "  --headless          render offscreen (EGL, no display needed); needs --seconds\n"
    "  --seconds T         stop after T simulated seconds (headless: T seconds are captured)\n"
    "  --start T0          headless: simulate T0 seconds first, without capturing (default 0)\n"
    "  --fps N             headless: frames per simulated second (default 30)\n"
    "  --frames DIR        write every frame as DIR/frame_00001.png, ...\n"
    "  --video FILE        encode the frames with ffmpeg: FILE.mp4 or FILE.gif\n"
    "  --screenshot FILE   write the last frame as a PNG\n"
    "  --size WxH          window or image size in pixels (default 1600x900; headless 1280x720)\n"
    "  --script FILE|demo|abdomen  scripted mouse, keys, tool and organ paths, screenshots\n"
    "                      (docs/viewer.md); demo: the demo's tool path (the default for --headless\n"
    "                      on the demo scene); abdomen: the retractor lifting the liver and the grasper\n"
    "                      of examples/scenes/abdomen.json (its default: the retractor alone in a window)\n"
    "  --skin METHOD       tube, point_skeleton or convolution (default convolution)\n"
    "  --laparoscope       look through a 30-degree laparoscope from the umbilical port, its\n"
    "                      light at its tip (key V switches; docs/viewer.md)\n"
    "  --ui MODE           full (panels), hud (a small overlay) or none (default: full; headless: hud)\n"
    "  --rate R            slow motion: simulated seconds per wall second, (0, 1] (default 1)\n"
    "  --lcm URL           show the session of an enteron-lcm-server there instead of a scene here\n"
    "                      (e.g. udpm://239.255.76.67:7667?ttl=0); the mouse sends tool_command_t;\n"
    "                      headless, --seconds and the script's times are wall seconds\n"
    "  --channel-suffix S  with --lcm: the server's --channel-suffix\n"
    "Exit status: 0 done; 1 the scene did not load, a library call failed or an output could not be\n"
    "written; 2 a bad command line; 3 no OpenGL 3.3 context could be made.\n";

bool parse_number(const char* text, double low, double high, double& out) {
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(value) || value < low || value > high) return false;
    out = value;
    return true;
}

int usage_error(const std::string& message) {
    std::fprintf(stderr, "enteron-viewer: %s\n%s", message.c_str(), kUsage);
    return viewer::kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace viewer;
    const std::uint32_t version = ent_version();
    if ((version >> 16) != ENT_VERSION_MAJOR) {
        std::fprintf(stderr, "enteron-viewer: libenteron major version %u, built for %d\n", version >> 16,
                     ENT_VERSION_MAJOR);
        return kExitFailed;
    }
    ViewerSettings settings;
    RunOptions options;
    bool headless = false, ui_given = false, size_given = false;
    std::string script_name;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        auto number = [&](double low, double high, double& out) {
            if (!has_value || !parse_number(argv[++i], low, high, out))
                return usage_error(arg + " wants a number in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
            return 0;
        };
        if (arg == "-h" || arg == "--help") {
            std::fputs(kUsage, stdout);
            return kExitOk;
        } else if (arg == "--headless") {
            headless = true;
        } else if (arg == "--laparoscope") {
            settings.laparoscope = true;
        } else if (arg == "--seconds") {
            if (int bad = number(1e-3, 3600.0, options.seconds)) return bad;
        } else if (arg == "--start") {
            if (int bad = number(0.0, 3600.0, options.start_s)) return bad;
        } else if (arg == "--fps") {
            if (int bad = number(1.0, 240.0, options.fps)) return bad;
        } else if (arg == "--rate") {
            if (int bad = number(1.0 / 1024.0, 1.0, settings.session.rate)) return bad;
        } else if ((arg == "--frames" || arg == "--video" || arg == "--screenshot" || arg == "--script" ||
                    arg == "--skin" || arg == "--ui" || arg == "--size" || arg == "--lcm" ||
                    arg == "--channel-suffix") && has_value) {
            const std::string value = argv[++i];
            if (arg == "--lcm") settings.lcm_url = value;
            if (arg == "--channel-suffix") settings.lcm_channel_suffix = value;
            if (arg == "--frames") options.frames_dir = value;
            if (arg == "--video") options.video_path = value;
            if (arg == "--screenshot") options.screenshot_path = value;
            if (arg == "--script") script_name = value;
            if (arg == "--skin") {
                ent_skin_desc_default(&settings.session.skin);
                settings.session.skin.method = skin_method_named(value);
                if (settings.session.skin.method < 0)
                    return usage_error("--skin wants tube, point_skeleton or convolution, got " + value);
            }
            if (arg == "--ui") {
                ui_given = true;
                if (value == "full") settings.ui = UiMode::full;
                else if (value == "hud") settings.ui = UiMode::hud;
                else if (value == "none") settings.ui = UiMode::none;
                else return usage_error("--ui wants full, hud or none, got " + value);
            }
            if (arg == "--size") size_given = true;
            if (arg == "--size" && (std::sscanf(value.c_str(), "%dx%d", &options.width, &options.height) != 2 ||
                                    options.width < 64 || options.height < 64 || options.width > 8192 ||
                                    options.height > 8192))
                return usage_error("--size wants WxH, each 64 to 8192, got " + value);
        } else if (!arg.empty() && arg[0] != '-' && settings.scene_path.empty()) {
            settings.scene_path = arg;
        } else {
            return usage_error("unknown or incomplete argument " + arg);
        }
    }
    if (headless && options.seconds <= 0.0) return usage_error("--headless needs --seconds");
    const std::string& video = options.video_path;
    if (!video.empty() && !(video.size() > 4 && (video.compare(video.size() - 4, 4, ".mp4") == 0 ||
                                                 video.compare(video.size() - 4, 4, ".gif") == 0)))
        return usage_error("--video wants a .mp4 or .gif file, got " + video);
    if (headless && !ui_given) settings.ui = UiMode::hud;
    if (headless && !size_given) options.width = 1280, options.height = 720;
    const bool remote = !settings.lcm_url.empty();
    if (remote && !settings.scene_path.empty()) return usage_error("--lcm shows the server's scene: give no SCENE.json");
    if (!remote && !settings.lcm_channel_suffix.empty()) return usage_error("--channel-suffix goes with --lcm");
    // A scene with a motion of its own (demo_scene.h: the demo scene's tool path, the
    // abdomen's retractor and grasper) plays it unless a script is given: headless all of
    // it; in a window the organs' part, the mouse being the tool.
    settings.scene_motion = script_name.empty() && !remote;
    settings.scene_motion_tool = headless;
    if (!script_name.empty()) {
        std::string error;
        if (!options.script.load(script_name, error)) return usage_error(error);
        // Tool and organ paths are played by a local physics thread; a remote tool follows the mouse.
        const ScenePaths& paths = options.script.paths();
        if (remote && (!paths.tool0.empty() || !paths.obstacles.empty()))
            return usage_error("with --lcm a script drives the tool with mouse lines, not tool lines (nor obstacle lines)");
        settings.session.tool0_path = paths.tool0;
        settings.session.obstacle_paths = paths.obstacles;
    }
    // The simulation waits for the picture: headless, for frame 1's time; in a window, at
    // t = 0 until the window shows its first frame (Viewer::start_clock).
    settings.session.gate_s = headless ? options.start_s + 1.0 / options.fps : 0.0;

    Viewer viewer(settings);
    std::string error;
    const bool loaded = viewer.open_initial(error);
    if (!loaded) {
        std::fprintf(stderr, "enteron-viewer: %s\n", error.c_str());
        if (headless) return kExitFailed;  // nothing to capture; a window still shows the error
    }
    const int status = headless ? run_headless(viewer, options) : run_window(viewer, options);
    return status == kExitOk && !loaded ? kExitFailed : status;
}
