// SPDX-License-Identifier: Apache-2.0
#include "script.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <sstream>

#include "demo_scene.h"
#include "local_session.h"  // read_text_file
#include "viewer.h"

namespace viewer {

namespace {

// A key as a script names it: a letter, a digit, or one of these names.
int key_code(const std::string& name) {
    if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0])))
        return GLFW_KEY_A + (std::toupper(static_cast<unsigned char>(name[0])) - 'A');
    if (name.size() == 1 && std::isdigit(static_cast<unsigned char>(name[0]))) return GLFW_KEY_0 + (name[0] - '0');
    static const std::pair<const char*, int> names[] = {
        {"space", GLFW_KEY_SPACE}, {"right", GLFW_KEY_RIGHT},       {"backspace", GLFW_KEY_BACKSPACE},
        {"tab", GLFW_KEY_TAB},     {"home", GLFW_KEY_HOME},         {"f1", GLFW_KEY_F1},
        {"[", GLFW_KEY_LEFT_BRACKET}, {"]", GLFW_KEY_RIGHT_BRACKET}};
    for (const auto& [text, code] : names)
        if (name == text) return code;
    return -1;
}

}  // namespace

ScenePaths scene_paths(const demo_motion* motion) {
    ScenePaths paths;
    if (motion == nullptr) return paths;
    paths.tool0.assign(motion->tool_keys, motion->tool_keys + 4 * motion->tool_key_count);
    if (motion->obstacle >= 0)
        paths.obstacles.push_back(ObstaclePath{
            motion->obstacle, std::vector<double>(motion->obstacle_keys, motion->obstacle_keys + 4 * motion->obstacle_key_count)});
    return paths;
}

bool Script::load(const std::string& path_or_motion, std::string& error) {
    if (const demo_motion* motion = demo_motion_named(path_or_motion.c_str())) {
        paths_ = scene_paths(motion);
        return true;
    }
    std::string text;
    return read_text_file(path_or_motion, text, error) && parse(text, path_or_motion, error);
}

bool Script::parse(const std::string& text, const std::string& name, std::string& error) {
    std::istringstream lines(text);
    std::string line;
    std::vector<std::array<double, 4>> tool_keys;
    std::vector<std::pair<std::int32_t, std::array<double, 4>>> obstacle_keys;
    for (int number = 1; std::getline(lines, line); ++number) {
        const std::string content = line.substr(0, line.find('#'));
        std::istringstream words(content);
        double time_s;
        std::string kind;
        if (!(words >> time_s)) {
            if (content.find_first_not_of(" \t\r") == std::string::npos) continue;
            error = name + ":" + std::to_string(number) + ": a line starts with a time in seconds";
            return false;
        }
        auto bad = [&](const std::string& what) {
            error = name + ":" + std::to_string(number) + ": " + what;
            return false;
        };
        if (!(words >> kind)) return bad("an event after the time (mouse, wheel, key, screenshot, tool, obstacle)");
        if (kind == "mouse") {
            MouseKey key{time_s, 0.0, 0.0, false};
            std::string button;
            if (!(words >> key.x >> key.y >> button) || (button != "down" && button != "up"))
                return bad("mouse wants X Y down|up");
            key.down = button == "down";
            mouse_.push_back(key);
        } else if (kind == "wheel") {
            Event event{time_s, Event::Kind::wheel, 0.0, 0, ""};
            if (!(words >> event.notches)) return bad("wheel wants a number of notches");
            events_.push_back(event);
        } else if (kind == "key") {
            std::string key;
            Event event{time_s, Event::Kind::key, 0.0, -1, ""};
            if (!(words >> key) || (event.key = key_code(key)) < 0) return bad("key wants a letter, a digit or a key name");
            events_.push_back(event);
        } else if (kind == "screenshot") {
            Event event{time_s, Event::Kind::screenshot, 0.0, 0, ""};
            if (!(words >> event.path)) return bad("screenshot wants a file name");
            events_.push_back(event);
        } else if (kind == "tool") {
            std::array<double, 4> key{time_s, 0.0, 0.0, 0.0};
            if (!(words >> key[1] >> key[2] >> key[3])) return bad("tool wants X Y Z in m");
            tool_keys.push_back(key);
        } else if (kind == "obstacle") {
            long id = -1;
            std::array<double, 4> key{time_s, 0.0, 0.0, 0.0};
            if (!(words >> id >> key[1] >> key[2] >> key[3]) || id < 0 || id > 1000000)
                return bad("obstacle wants an obstacle number (from 0) and DX DY DZ in m");
            obstacle_keys.emplace_back(static_cast<std::int32_t>(id), key);
        } else {
            return bad("unknown event \"" + kind + "\" (mouse, wheel, key, screenshot, tool, obstacle)");
        }
    }
    auto earlier = [](const auto& a, const auto& b) { return a.time_s < b.time_s; };
    std::stable_sort(mouse_.begin(), mouse_.end(), earlier);
    std::stable_sort(events_.begin(), events_.end(), earlier);
    std::stable_sort(tool_keys.begin(), tool_keys.end(), [](const auto& a, const auto& b) { return a[0] < b[0]; });
    for (const auto& key : tool_keys) paths_.tool0.insert(paths_.tool0.end(), key.begin(), key.end());
    // Each obstacle's keys in time order, one path per obstacle.
    std::stable_sort(obstacle_keys.begin(), obstacle_keys.end(),
                     [](const auto& a, const auto& b) { return a.second[0] < b.second[0]; });
    for (const auto& [id, key] : obstacle_keys) {
        auto path = std::find_if(paths_.obstacles.begin(), paths_.obstacles.end(),
                                 [id = id](const ObstaclePath& p) { return p.obstacle == id; });
        if (path == paths_.obstacles.end()) path = paths_.obstacles.insert(paths_.obstacles.end(), ObstaclePath{id, {}});
        path->keys.insert(path->keys.end(), key.begin(), key.end());
    }
    return true;
}

void Script::play(double time_s, Viewer& viewer, std::vector<std::string>& screenshots) {
    // The pointer: every key passed since the last frame, then the way to the next one.
    for (; next_mouse_ < mouse_.size() && mouse_[next_mouse_].time_s <= time_s; ++next_mouse_) {
        const MouseKey& key = mouse_[next_mouse_];
        if (key.x != pointer_x_ || key.y != pointer_y_) viewer.mouse_move(key.x, key.y);
        pointer_x_ = key.x;
        pointer_y_ = key.y;
        if (key.down != button_down_) viewer.mouse_button(GLFW_MOUSE_BUTTON_LEFT, key.down, 0, key.x, key.y);
        button_down_ = key.down;
    }
    if (next_mouse_ > 0 && next_mouse_ < mouse_.size()) {
        const MouseKey& a = mouse_[next_mouse_ - 1];
        const MouseKey& b = mouse_[next_mouse_];
        const double f = (time_s - a.time_s) / std::max(b.time_s - a.time_s, 1e-9);
        pointer_x_ = a.x + f * (b.x - a.x);
        pointer_y_ = a.y + f * (b.y - a.y);
        viewer.mouse_move(pointer_x_, pointer_y_);
    }
    for (; next_event_ < events_.size() && events_[next_event_].time_s <= time_s; ++next_event_) {
        const Event& event = events_[next_event_];
        switch (event.kind) {
            case Event::Kind::wheel: viewer.scroll(event.notches, 0); break;
            case Event::Kind::key: viewer.key(event.key, 0); break;
            case Event::Kind::screenshot: screenshots.push_back(event.path); break;
        }
    }
}

}  // namespace viewer
