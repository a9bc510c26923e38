// SPDX-License-Identifier: Apache-2.0
// The scene description as a table (field_table.h): every key of a JSON v1 scene
// (docs/scene-json.md), its place in SceneConfig, its rule, its plausible range and its
// ent_scene_desc field, one row each, for the scene and its parts (the intestine and its
// shape, the solver, gravity, damping, the mesentery, the pins, the contact law, the
// obstacles, the tools). The JSON loader reads a document by it, validate() checks a config
// by it, the C descriptions fill and read their structs by it (lib/capi), and the
// documentation test checks that docs/scene-json.md documents each key.
//
// A new setting is one row here (and its member, with its default, in scene_config.h;
// for C, its field in ent_scene_desc and the line that binds it in lib/capi/scene_desc.cpp).
#pragma once

#include <string>

#include "scene/field_table.h"

namespace enteron::scene {

// The top level of a scene (a SceneConfig).
const Block& scene_block();
// An element of "environment" (a collision::Obstacle), typed by its "type".
const Block& obstacle_block();
// An element of "tools" (a collision::ToolConfig); ent_tool_desc.
const Block& tool_block();

// A field found in a table, with the object rows that lead to it from the table's top
// (intestine.shape.kind: the rows "intestine" and "shape", then "kind"). Lists are not
// entered: their elements are parts of their own.
struct FieldPath {
    const Field* objects[4] = {};
    std::size_t depth = 0;
    const Field* field = nullptr;

    explicit operator bool() const { return field != nullptr; }
    // The part that holds the field, from the top's part: null if an object on the way is
    // absent (an effect left off).
    const void* part(const void* top) const;
    // The same, making the absent objects on the way.
    void* make_part(void* top) const;
};

// The field at a JSON path ("intestine.shape.helix_pitch"), or whose C name is `c_name`
// ("shape_helix_pitch_m"); empty if there is none.
FieldPath find_path(const Block& top, const std::string& path);
FieldPath find_c_name(const Block& top, const char* c_name);

}  // namespace enteron::scene
