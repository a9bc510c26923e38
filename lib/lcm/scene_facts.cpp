// SPDX-License-Identifier: Apache-2.0
#include "lcm/scene_facts.h"

#include <string>

#include "base/error.h"

namespace enteron::lcm {

namespace {

void check(ent_status status, const char* call) {
    if (status != ENT_OK) throw Error(static_cast<ErrorCode>(status), std::string(call) + ": " + ent_last_error());
}

}  // namespace

SceneFacts read_scene_facts(const ent_scene* scene) {
    SceneFacts facts;
    ent_scene_desc description;
    ent_scene_desc_default(&description);
    check(ent_scene_read_desc(scene, &description), "ent_scene_read_desc");
    facts.radius_m = description.radius_m;

    int32_t tools = 0;
    check(ent_scene_tool_count(scene, &tools), "ent_scene_tool_count");
    for (int32_t id = 0; id < tools; ++id) {
        ent_tool_desc tool;
        ent_tool_desc_default(&tool);
        check(ent_tool_read_desc(scene, id, &tool), "ent_tool_read_desc");
        ToolFacts t;
        t.radius_m = tool.radius_m;
        t.length_m = tool.length_m;
        t.max_force_N = tool.max_force_N;
        t.initial_pose.position = Eigen::Vector3d(tool.position_m[0], tool.position_m[1], tool.position_m[2]);
        t.initial_pose.orientation = Eigen::Quaterniond(tool.orientation_wxyz[0], tool.orientation_wxyz[1],
                                                        tool.orientation_wxyz[2], tool.orientation_wxyz[3]);
        facts.tools.push_back(t);
    }
    return facts;
}

}  // namespace enteron::lcm
