// The one check of a scene description, shared by the JSON loader and the C desc
// conversion. The rules are written once; only the names in the messages and the error
// code differ, so a JSON user reads "intestine.radius must be > 0, got -1" and a C user
// reads "radius_m must be > 0, got -1".
#pragma once

#include <array>
#include <cstddef>

#include "base/error.h"
#include "scene/scene_config.h"

namespace enteron::scene {

// Every field that validate() checks.
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
    sphere_spacing,
    contact_stiffness,
    contact_damping,
    contact_friction,
    contact_slip_speed,
    obstacle,
    count  // not a field: the number of fields
};

constexpr std::size_t kFieldCount = static_cast<std::size_t>(Field::count);

// How the fields are called in messages, and what error a bad value raises.
// Elements of a vector or list are named by appending "[i]" to the field's name.
struct FieldNames {
    ErrorCode code;
    // JSON gives the shape points as one [x,y,z] per control point ("points[i][k]"); C gives
    // them flat ("shape_points_xyz_m[3 i + k]").
    bool shape_points_nested;
    std::array<const char*, kFieldCount> names;

    const char* operator[](Field field) const { return names[static_cast<std::size_t>(field)]; }
};

// JSON v1 paths ("intestine.radius", "solver.timestep", "mesentery.root[0]"), raising
// ErrorCode::invalid_scene.
const FieldNames& json_field_names();

// ent_scene_desc field names ("radius_m", "timestep_s", "pinned_points"), raising
// ErrorCode::invalid_argument.
const FieldNames& c_field_names();

// Checks every value of config that the scene will use (shape fields only for the chosen
// shape kind; optional effects only when present). Every number must be finite.
// Throws Error(names.code, message) for the first bad value, the message naming it:
// "intestine.radius must be > 0, got -1". Does nothing else.
void validate(const SceneConfig& config, const FieldNames& names);

// Checks one obstacle (kind in range, finite, sizes > 0, a non-zero plane normal); index
// names it in a list ("environment[2].radius must be > 0, got -1").
void validate_obstacle(const collision::Obstacle& obstacle, std::size_t index, const FieldNames& names);

}  // namespace enteron::scene
