// SPDX-License-Identifier: Apache-2.0
// What the bridge needs to know about its scene besides the state it publishes: each tool's
// size, max_force and initial pose, and the bowel's radius (for the state a viewer draws
// and for the force clamp). Asked of the scene itself (ent_scene_read_desc,
// ent_tool_read_desc): the bridge links libenteron through its C API only, and the scene
// knows its description as the library read it, defaults and normalised poses included.
#pragma once

#include <vector>

#include "enteron/enteron.h"
#include "lcm/workspace_mapping.h"

namespace enteron::lcm {

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

// The facts of a scene and of each of its tools (ids 0 to the count - 1). Throws
// enteron::Error with the library's status and message if a query fails.
SceneFacts read_scene_facts(const ent_scene* scene);

}  // namespace enteron::lcm
