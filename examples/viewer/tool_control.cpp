// SPDX-License-Identifier: Apache-2.0
#include "tool_control.h"

#include <algorithm>
#include <cmath>

namespace viewer {

void ToolControl::reset(const SceneLayout& layout) {
    commands_ = ToolCommands();
    commands_.count = static_cast<std::uint32_t>(std::min<std::size_t>(layout.tools.size(), kMaxTools));
    for (std::uint32_t i = 0; i < commands_.count; ++i) commands_.target[i] = layout.tools[i].initial;
    active_ = 0;
    dragging_ = false;
}

void ToolControl::begin_drag(const Camera& camera, const Ray& ray) {
    if (commands_.count == 0) return;
    plane_point_ = Eigen::Map<const Eigen::Vector3d>(commands_.target[active_].position_m);
    plane_normal_ = camera.forward();
    dragging_ = true;
    drag(ray);
}

void ToolControl::drag(const Ray& ray) {
    if (!dragging_) return;
    // Where the line of sight meets the plane: origin + s direction with
    // (origin + s direction - point) . normal = 0.
    const double facing = ray.direction.dot(plane_normal_);
    if (std::abs(facing) < 1e-6) return;
    const double s = (plane_point_ - ray.origin).dot(plane_normal_) / facing;
    if (s <= 0.0) return;
    Eigen::Map<Eigen::Vector3d>(commands_.target[active_].position_m) = ray.origin + s * ray.direction;
}

void ToolControl::push(const Camera& camera, double notches) {
    if (commands_.count == 0) return;
    const Eigen::Vector3d step = 0.01 * camera.distance() * notches * camera.forward();
    Eigen::Map<Eigen::Vector3d>(commands_.target[active_].position_m) += step;
    plane_point_ += step;  // a drag in progress goes on at the new depth
}

void ToolControl::set_grasp(bool closed) {
    if (commands_.count > 0) commands_.grasp[active_] = closed;
}

void ToolControl::set_active(std::uint32_t tool) {
    if (tool < commands_.count) {
        active_ = tool;
        dragging_ = false;
    }
}

}  // namespace viewer
