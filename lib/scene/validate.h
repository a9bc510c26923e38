// SPDX-License-Identifier: Apache-2.0
// The one check of a scene description, shared by the JSON loader and the C desc
// conversion. The rules are the rows of the description's table (scene_table.h) and the few
// between its parts written here; only the names in the messages and the error code differ,
// so a JSON user reads "intestine.radius must be > 0, got -1" and a C user reads
// "radius_m must be > 0, got -1".
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <memory_resource>
#include <set>
#include <string>
#include <vector>

#include "base/error.h"
#include "collision/obstacle.h"
#include "collision/tool.h"
#include "scene/checked_value.h"
#include "scene/field_table.h"
#include "scene/scene_config.h"

namespace enteron::scene {

// How fields are called in messages, and what error a bad value raises. JSON names a field
// by its path ("intestine.radius", "tools[1].radius", "mesentery.root[0]"); C by its
// ent_*_desc field ("radius_m"), after a prefix for an element of a list ("obstacle[2].",
// an obstacle's fields keeping their keys). Elements of a vector or list are named by
// appending "[i]"; JSON gives the shape points as one [x,y,z] per control point
// ("points[i][k]"), C flat ("shape_points_xyz_m[3 i + k]").
struct FieldNames {
    ErrorCode code;
    bool c_names;

    // The name of `field` of a part at JSON path `path` ("intestine.shape", "tools[1]"),
    // whose C names start with `prefix`.
    std::string of(const Field& field, const std::string& path, const std::string& prefix = "") const;
    // The C prefix of element `index` of the list `field` ("obstacle[2]."), from the list's.
    std::string element_prefix(const Field& field, const std::string& prefix, std::size_t index) const;
    // The name of the field at a JSON path from the top ("pinned.clamped", "intestine.length").
    std::string at(const std::string& path) const;
    // What the i-th obstacle is called: "environment[i]", "obstacle[i]".
    std::string obstacle(std::size_t index) const;
};

// JSON v1 paths, raising ErrorCode::invalid_scene.
const FieldNames& json_field_names();
// ent_scene_desc, ent_tool_desc and ent_obstacle_desc names, raising ErrorCode::invalid_argument.
const FieldNames& c_field_names();

// The JSON path of a key inside an object's path: ("intestine", "length") is
// "intestine.length"; ("", "intestine") is "intestine".
std::string join_path(const std::string& path, const std::string& key);
// The path of an array's element: ("intestine.shape.points", 2) is "intestine.shape.points[2]".
std::string index_path(const std::string& path, std::size_t index);

// The fields the caller wrote, by JSON path ("intestine.shape.helix_pitch"), as opposed to
// those left at their defaults: where two fields disagree, the message blames the written
// one. By default every field counts as written.
class FieldSet {
public:
    FieldSet() = default;
    static FieldSet none() {
        FieldSet set;
        set.all_ = false;
        return set;
    }
    void add(const std::string& path) { paths_.insert(path); }
    bool has(const std::string& path) const { return all_ || paths_.count(path) != 0; }

private:
    bool all_ = true;
    std::set<std::string> paths_;
};

// Whether a bowel can start where an obstacle is. A control point beyond the obstacle's
// surface (outside the box_inside, behind a plane, inside a sphere or capsule) is pushed
// back by its contacts, which works when it is shallow (a bowel draped over the cavity's
// rim falls in) but not when it is deep (a bowel outside its cavity, a 50 m helix in a
// 30 cm box): the contact spring, k per sphere of mass rho s, throws a sphere out at about
// depth sqrt(k / (rho s)), and past max_speed every step fails the guard.
// With a radius or a density profile each control point takes its own R and rho s (the
// profiles at its rest arc length; the spheres' spacing s follows the radius), in
// `radius_at` and `escape_rate_at` (empty without profiles).
struct StartClearance {
    double radius;       // R, m: a contact starts R before the centre reaches the surface
    double escape_rate;  // sqrt(k / (rho s)), 1/s: escape speed per metre of contact depth
    double max_speed;    // m/s, the guard's
    std::pmr::vector<double> radius_at, escape_rate_at;  // per control point, with profiles

    double radius_of(std::size_t i) const { return radius_at.empty() ? radius : radius_at[i]; }
    double escape_rate_of(std::size_t i) const { return escape_rate_at.empty() ? escape_rate : escape_rate_at[i]; }
    // The depth beyond the surface past which control point i escapes faster than max_speed, m.
    double deepest_possible(std::size_t i) const { return max_speed / escape_rate_of(i) - radius_of(i); }
};
// (The per-point values allocate from `memory`: the scene's, which keeps them.)
StartClearance start_clearance(const SceneConfig& config,
                               std::pmr::memory_resource* memory = std::pmr::get_default_resource());

// Checks every value of config that the scene will use (shape fields only for the chosen
// shape kind; optional effects only when present), then where the bowel starts: no control
// point may lie so far beyond an obstacle's surface that it cannot start (StartClearance).
// Every number must be finite. Returns the config normalised: tool and obstacle poses with
// unit quaternions, and start_points, the initial control points of the shape.
// Throws Error(names.code, message) for the first bad value, the message naming it:
// "intestine.radius must be > 0, got -1". Where two fields must agree (radius and
// helix_pitch, ...), the message blames the one the caller wrote (`given`), and says so
// when the other still has its default.
SceneConfig validate(SceneConfig config, const FieldNames& names, const FieldSet& given = FieldSet());

// The fields of config whose value differs from the default (the defaults of an effect
// that config turns on are those it starts with): what a C caller changed after
// ent_scene_desc_default.
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

// A rotation given as a quaternion w x y z, made unit: each coordinate must be finite and
// the norm above 1e-12, else Error(code) naming it ("orientation_wxyz must be a non-zero
// quaternion (w x y z), got one of norm 0"). `name()` is called only for a message, so a
// valid rotation costs no allocation.
template <typename Name>
std::array<double, 4> unit_quaternion(const std::array<double, 4>& q, const Name& name, ErrorCode code) {
    double norm2 = 0.0;
    for (std::size_t c = 0; c < 4; ++c) {
        if (!std::isfinite(q[c])) Checked<double>(q[c], name() + "[" + std::to_string(c) + "]", code);
        norm2 += q[c] * q[c];
    }
    const double norm = std::sqrt(norm2);
    if (!(norm > 1e-12) || !std::isfinite(norm))
        throw Error(code, name() + " must be a non-zero quaternion (w x y z), got one of norm " + format_number(norm));
    return {q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm};
}

// Checks a tool's settings and pose, its fields named with `prefix` ("tools[1].", or ""
// in C); returns it with a unit quaternion.
collision::ToolConfig validate_tool(const collision::ToolConfig& tool, const std::string& prefix,
                                    const FieldNames& names);
// The same for its pose alone, allocating nothing unless it throws (ent_tool_set_pose, 1 kHz).
collision::ToolPose validate_tool_pose(const collision::ToolPose& pose, const std::string& prefix,
                                       const FieldNames& names);

}  // namespace enteron::scene
