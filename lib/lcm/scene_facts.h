// SPDX-License-Identifier: Apache-2.0
// What the bridge needs to know about its scene that the public API does not report: each
// tool's size, max_force and initial pose, and the bowel's radius (for the state a viewer
// draws and for the force clamp). Read from the scene JSON after libenteron accepted it,
// with the defaults of ent_tool_desc_default / ent_scene_desc_default for keys it omits
// (the JSON loader and the C descriptions share those defaults).
#pragma once

#include <cstddef>
#include <vector>

#include "workspace_mapping.h"

namespace enteron::bridge {

struct ToolFacts {
    double radius_m = 0.0;
    double length_m = 0.0;
    double max_force_N = 0.0;
    Pose initial_pose;  // scene frame, orientation unit
};

struct SceneFacts {
    double radius_m = 0.0;  // the intestine's R
    std::vector<ToolFacts> tools;
};

// Throws enteron::Error(invalid_scene) if the text is not the object libenteron accepted.
SceneFacts read_scene_facts(const char* json, std::size_t length);

}  // namespace enteron::bridge
