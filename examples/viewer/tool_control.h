// SPDX-License-Identifier: Apache-2.0
// The mouse as the surgical tool. While the left button is held, the active tool's tip
// follows the pointer on the plane that faces the camera through the tip (fixed when the
// button went down); the wheel moves the tip along the line of sight, in depth; a key or
// the right button closes and opens the jaws. The result is a target the physics thread
// moves the tool toward (tool_exchange.h).
#pragma once

#include <Eigen/Core>

#include "camera.h"
#include "scene_layout.h"
#include "tool_exchange.h"

namespace viewer {

class ToolControl {
public:
    // Targets at the tools' initial poses, jaws open.
    void reset(const SceneLayout& layout);

    void begin_drag(const Camera& camera, const Ray& ray);
    void drag(const Ray& ray);
    void end_drag() { dragging_ = false; }
    bool dragging() const { return dragging_; }
    // Moves the tip along the line of sight: > 0 away from the eye. A notch is 1 % of the
    // camera's distance, so it feels the same at any zoom.
    void push(const Camera& camera, double notches);
    void set_grasp(bool closed);
    void toggle_grasp() { set_grasp(!commands_.grasp[active_]); }

    void set_active(std::uint32_t tool);
    std::uint32_t active() const { return active_; }
    std::uint32_t count() const { return commands_.count; }

    // What the panels edit directly.
    ToolCommands& commands() { return commands_; }
    const ToolCommands& commands() const { return commands_; }

private:
    ToolCommands commands_;
    std::uint32_t active_ = 0;
    bool dragging_ = false;
    Eigen::Vector3d plane_point_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d plane_normal_ = Eigen::Vector3d::UnitZ();
};

}  // namespace viewer
