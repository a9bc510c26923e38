// SPDX-License-Identifier: Apache-2.0
// What the viewer draws besides the bowel, read from the scene's JSON description: the
// tube radius, the obstacles, the tools' capsules, the mesentery's root, the number of
// collision spheres. The C API has no call that returns a scene's description, so the
// viewer reads the same text the library was given (after the library accepted it), with
// the library's own defaults (ent_*_desc_default) for the keys the text leaves out. A mesh
// obstacle's triangles come from the library itself (ent_obstacle_mesh, LocalSession), so
// the viewer draws what the contacts meet, whatever file format or scale the scene used.
#pragma once

#include <cstdint>
#include <memory>
#include <array>
#include <string>
#include <vector>

#include "tool_exchange.h"

namespace viewer {

// A mesh obstacle's triangles in its frame, ready to draw.
struct OrganMesh {
    std::vector<float> positions;         // 3 per vertex, m
    std::vector<float> normals;           // 3 per vertex: area-weighted, unit, the triangles' side
    std::vector<std::uint32_t> indices;   // 3 per triangle
    bool cavity = false;                  // normals in (negative signed volume): a wall seen from inside
    float low_m[3] = {}, high_m[3] = {};  // the box around the vertices
};

// The triangles and vertex normals of a mesh (vertices x y z, triangles 3 indices each,
// indices in range).
std::shared_ptr<const OrganMesh> make_organ_mesh(const std::vector<double>& vertices_xyz_m,
                                                 const std::vector<std::uint32_t>& triangles);

struct ObstacleShape {
    std::int32_t kind = 0;            // ENT_OBSTACLE_*
    double center_m[3] = {};          // box, sphere centre; plane point
    double half_extents_m[3] = {};    // box
    double normal[3] = {0, 0, 1};     // plane, unit
    double start_m[3] = {}, end_m[3] = {};  // capsule
    double radius_m = 0.0;            // sphere, capsule
    double position_m[3] = {};        // its frame in the description (the shape's fields are in it)
    double orientation_wxyz[4] = {1, 0, 0, 0};
    std::string name;                 // mesh: its file ("organs/liver.obj"), for its colour
    std::shared_ptr<const OrganMesh> mesh;  // mesh: null until read from the library (not remotely)
};

struct ToolShape {
    double radius_m = 0.0, length_m = 0.0, max_force_N = 0.0;
    double blade_width_m = 0.0, blade_length_m = 0.0;  // a retractor's blade at the tip (0: none)
    ToolPose initial;
};

struct SceneLayout {
    double length_m = 0.0;            // rest length of the axis
    double radius_m = 0.0;            // tube radius R
    std::uint32_t control_points = 0;
    std::uint32_t collision_spheres = 0;  // round(length / spacing) + 1
    double timestep_s = 0.0;          // the solver's largest substep
    bool mesentery = false;
    std::vector<double> root_m;          // the root polyline, x y z per point (two: the segment)
    std::vector<double> root_mapping;    // pairs (s m, t): where along the root the bowel at s is tied
    std::uint32_t attachments = 0;
    std::vector<ObstacleShape> obstacles;
    std::vector<ToolShape> tools;
    double scene_center_m[3] = {};    // a point the camera should look at
    double scene_size_m = 0.3;        // and how much it should see
    double port_m[3] = {};            // the umbilical port: the cavity's top above its centre
    bool port_known = false;          // false: no cavity
};

// The root's point tied to the bowel at fraction f of its length, as the library ties it
// (lib/mechanics/mesentery_force.h): at the fraction t = f of the root's length, or t(s)
// from the mapping, walked along the polyline.
std::array<double, 3> mesentery_root_point(const SceneLayout& layout, double f);

// Reads the layout of a JSON description that ent_scene_create_json accepted. False (with
// a message) only if the text is not JSON after all.
bool read_scene_layout(const std::string& json, SceneLayout& layout, std::string& error);

// Frames the camera on the cavity: an inside box, else a mesh whose normals point in (at
// its pose in the description); neither: scene_size_m 0 (the bowel frames it). Again
// after the meshes arrive.
void frame_on_cavity(SceneLayout& layout);

// The description with each mesh obstacle's relative "file" made relative to scene_dir
// (where the scene file is), as ent_scene_create_json_file would find it; the text as it
// is when there is nothing to change or it is not JSON (the library then says why).
std::string with_mesh_files_from(const std::string& json, const std::string& scene_dir);

}  // namespace viewer
