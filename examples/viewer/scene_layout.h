// What the viewer draws besides the bowel, read from the scene's JSON description: the
// tube radius, the obstacles, the tools' capsules, the mesentery's root, the number of
// collision spheres. The C API has no call that returns a scene's description, so the
// viewer reads the same text the library was given (after the library accepted it), with
// the library's own defaults (ent_*_desc_default) for the keys the text leaves out.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tool_exchange.h"

namespace viewer {

struct ObstacleShape {
    std::int32_t kind = 0;            // ENT_OBSTACLE_*
    double center_m[3] = {};          // box, sphere centre; plane point
    double half_extents_m[3] = {};    // box
    double normal[3] = {0, 0, 1};     // plane, unit
    double start_m[3] = {}, end_m[3] = {};  // capsule
    double radius_m = 0.0;            // sphere, capsule
};

struct ToolShape {
    double radius_m = 0.0, length_m = 0.0, max_force_N = 0.0;
    ToolPose initial;
};

struct SceneLayout {
    double length_m = 0.0;            // rest length of the axis
    double radius_m = 0.0;            // tube radius R
    std::uint32_t control_points = 0;
    std::uint32_t collision_spheres = 0;  // round(length / spacing) + 1
    double timestep_s = 0.0;          // the solver's largest substep
    bool mesentery = false;
    double root_start_m[3] = {}, root_end_m[3] = {};
    std::uint32_t attachments = 0;
    std::vector<ObstacleShape> obstacles;
    std::vector<ToolShape> tools;
    double scene_center_m[3] = {};    // a point the camera should look at
    double scene_size_m = 0.3;        // and how much it should see
};

// Reads the layout of a JSON description that ent_scene_create_json accepted. False (with
// a message) only if the text is not JSON after all.
bool read_scene_layout(const std::string& json, SceneLayout& layout, std::string& error);

}  // namespace viewer
