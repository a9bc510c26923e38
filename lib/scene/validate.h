// SPDX-License-Identifier: Apache-2.0
// The one check of a scene description, shared by the JSON loader and the C desc
// conversion. The rules are written once; only the names in the messages and the error
// code differ, so a JSON user reads "intestine.radius must be > 0, got -1" and a C user
// reads "radius_m must be > 0, got -1".
#pragma once

#include <array>
#include <bitset>
#include <cstddef>
#include <string>

#include "base/error.h"
#include "collision/obstacle.h"
#include "collision/tool.h"
#include "scene/scene_config.h"

namespace enteron::scene {

// Every field of the scene description that validate() checks.
enum class Field : std::size_t {
    length,
    radius,
    control_points,
    linear_density,
    stretch_stiffness,
    bend_stiffness,
    shape_kind,
    shape_center,
    shape_direction,
    shape_leg_length,
    shape_leg_spacing,
    shape_helix_radius,
    shape_helix_pitch,
    shape_points,
    integrator,
    timestep,
    max_substeps,
    max_subdivisions,
    max_speed,
    gravity,
    drag,
    stretch_damping,
    bend_damping,
    mesentery_root_start,
    mesentery_root_end,
    mesentery_attachments,
    mesentery_stiffness,
    mesentery_rest_length,
    pinned_ends,
    pinned_points,
    pinned_clamped,
    sphere_spacing,
    contact_stiffness,
    contact_damping,
    contact_friction,
    contact_slip_speed,
    obstacle,
    count  // not a field: the number of fields
};

constexpr std::size_t kFieldCount = static_cast<std::size_t>(Field::count);

// A set of fields: those the caller wrote, as opposed to those left at their defaults.
using FieldSet = std::bitset<kFieldCount>;

// How a tool's fields are called in messages (JSON keys or ent_tool_desc fields).
struct ToolFieldNames {
    const char* radius;
    const char* length;
    const char* max_force;
    const char* grasp_margin;
    const char* grasp_stiffness;
    const char* grasp_damping;
    const char* position;
    const char* orientation;
    const char* mode;
    const char* coupling_stiffness;
    const char* coupling_damping;
    const char* friction;
};

// How the fields are called in messages, and what error a bad value raises.
// Elements of a vector or list are named by appending "[i]" to the field's name.
struct FieldNames {
    ErrorCode code;
    // JSON gives the shape points as one [x,y,z] per control point ("points[i][k]"); C gives
    // them flat ("shape_points_xyz_m[3 i + k]").
    bool shape_points_nested;
    std::array<const char*, kFieldCount> names;
    ToolFieldNames tool;

    const char* operator[](Field field) const { return names[static_cast<std::size_t>(field)]; }
};

// JSON v1 paths ("intestine.radius", "solver.timestep", "mesentery.root[0]"), raising
// ErrorCode::invalid_scene.
const FieldNames& json_field_names();

// ent_scene_desc and ent_tool_desc field names ("radius_m", "timestep_s",
// "pinned_points"), raising ErrorCode::invalid_argument.
const FieldNames& c_field_names();

// Whether a bowel can start where an obstacle is. A control point beyond the obstacle's
// surface (outside the box_inside, behind a plane, inside a sphere or capsule) is pushed
// back by its contacts, which works when it is shallow (a bowel draped over the cavity's
// rim falls in) but not when it is deep (a bowel outside its cavity, a 50 m helix in a
// 30 cm box): the contact spring, k per sphere of mass rho s, throws a sphere out at about
// depth sqrt(k / (rho s)), and past max_speed every step fails the guard.
struct StartClearance {
    double radius;       // R, m: a contact starts R before the centre reaches the surface
    double escape_rate;  // sqrt(k / (rho s)), 1/s: escape speed per metre of contact depth
    double max_speed;    // m/s, the guard's
};
StartClearance start_clearance(const SceneConfig& config);

// Checks every value of config that the scene will use (shape fields only for the chosen
// shape kind; optional effects only when present), then where the bowel starts: no control
// point may lie so far beyond an obstacle's surface that it cannot start (StartClearance).
// Every number must be finite. Returns the config
// normalised: tool poses with unit quaternions, and start_points, the initial control
// points of the shape.
// Throws Error(names.code, message) for the first bad value, the message naming it:
// "intestine.radius must be > 0, got -1". Where two fields must agree (radius and
// helix_pitch, ...), the message blames the one the caller wrote (`given`), and says so
// when the other still has its default.
SceneConfig validate(SceneConfig config, const FieldNames& names, const FieldSet& given = FieldSet().set());

// The fields of config (among those that take part in a rule between two fields) whose
// value differs from the default: what a C caller changed after ent_scene_desc_default.
FieldSet fields_apart_from_defaults(const SceneConfig& config);

// Checks one obstacle (kind in range, finite, sizes > 0, a non-zero plane normal, a mesh's
// vertices finite and indices in range, a non-zero orientation), named `name`
// ("environment[2]", "obstacle[0]"): "environment[2].radius must be > 0, got -1". Returns it
// with a unit orientation. With control points (count x 3, m) and a clearance, also
// refuses an obstacle that has some of them too far beyond its surface to start (as
// validate() does), naming which; a mesh only once its field is prepared.
collision::Obstacle validate_obstacle(const collision::Obstacle& obstacle, const std::string& name,
                                     const FieldNames& names, const double* control_points = nullptr,
                                     std::size_t count = 0, const StartClearance* clearance = nullptr);

// Checks a tool's settings and pose, its fields named with `prefix` ("tools[1].", or ""
// in C); returns it with a unit quaternion.
collision::ToolConfig validate_tool(const collision::ToolConfig& tool, const std::string& prefix,
                                    const FieldNames& names);
collision::ToolPose validate_tool_pose(const collision::ToolPose& pose, const std::string& prefix,
                                       const FieldNames& names);

}  // namespace enteron::scene
