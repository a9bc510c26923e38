// SPDX-License-Identifier: Apache-2.0
// A scripted session: what a user's hands would do, at given simulated times, so that
// pictures, videos and tests can be made without anyone at the mouse. One event a line:
//
//   # time_s  event       arguments
//   1.0       mouse       640 360 down   pointer at pixel (640, 360), left button held;
//   2.0       mouse       900 360 down   between two mouse lines the pointer moves in a
//   2.1       mouse       900 360 up     straight line (a drag, through the same code as
//                                        the real mouse)
//   1.5       wheel       -3             wheel notches (forward > 0: the tool goes deeper)
//   0.5       key         G              a key, as typed (G grasps; see docs/viewer.md)
//   0.9       screenshot  before.png     this frame as a PNG
//   2.0       tool        0.1 0 -0.08    tool 0's tip in m: tool 0 then follows the path
//                                        through its tool lines instead of the mouse,
//                                        played on the physics thread like a device
//   1.5       obstacle    1 0 0 0.04     obstacle 1 (in the scene's order) displaced by
//                                        (0, 0, 4 cm) from where the scene put it: it
//                                        follows its obstacle lines (a retractor), played
//                                        on the physics thread before every step
//
// Times are simulated seconds, so a script plays the same at any frame rate; a pause stops
// its clock too, so a script that pauses resumes at the same time ("3 key space" twice).
// "demo" instead of a file name is the demo's tool path, "abdomen" the abdomen scene's
// retractor and grasper (examples/demo_scene.h, demo_motions).
#pragma once

#include <string>
#include <vector>

#include "physics_thread.h"

struct demo_motion;  // demo_scene.h

namespace viewer {

class Viewer;

// What a session plays on its physics thread: tool 0's path and the obstacles'.
struct ScenePaths {
    ToolPathKeys tool0;
    std::vector<ObstaclePath> obstacles;
};

// A motion of demo_scene.h as paths; nothing for null.
ScenePaths scene_paths(const demo_motion* motion);

class Script {
public:
    // Parses script text; false with "FILE:LINE: what is wrong".
    bool parse(const std::string& text, const std::string& name, std::string& error);
    bool load(const std::string& path_or_motion, std::string& error);

    const ScenePaths& paths() const { return paths_; }
    // Render thread, once a frame at simulated time time_s: the input events due go to
    // the viewer, the pointer moves along its path; the screenshots due are appended.
    void play(double time_s, Viewer& viewer, std::vector<std::string>& screenshots);

private:
    struct MouseKey {
        double time_s, x, y;
        bool down;
    };
    struct Event {
        double time_s;
        enum class Kind { wheel, key, screenshot } kind;
        double notches;
        int key;
        std::string path;
    };
    std::vector<MouseKey> mouse_;
    std::vector<Event> events_;
    ScenePaths paths_;
    std::size_t next_mouse_ = 0, next_event_ = 0;
    bool button_down_ = false;
    double pointer_x_ = -1.0, pointer_y_ = -1.0;
};

}  // namespace viewer
