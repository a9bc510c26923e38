// SPDX-License-Identifier: Apache-2.0
#include "scene_facts.h"

#include <nlohmann/json.hpp>

#include "base/error.h"
#include "enteron/enteron.h"

namespace enteron::bridge {

namespace {

using nlohmann::json;

double number_or(const json& object, const char* key, double fallback) {
    const auto it = object.find(key);
    return it != object.end() && it->is_number() ? it->get<double>() : fallback;
}

}  // namespace

SceneFacts read_scene_facts(const char* json_text, std::size_t length) {
    const json scene = json::parse(json_text, json_text + length, nullptr, /*allow_exceptions=*/false);
    if (!scene.is_object()) throw Error(ErrorCode::invalid_scene, "the scene JSON is not an object");

    ent_scene_desc scene_defaults;
    ent_scene_desc_default(&scene_defaults);
    ent_tool_desc tool_defaults;
    ent_tool_desc_default(&tool_defaults);

    SceneFacts facts;
    facts.radius_m = scene_defaults.radius_m;
    if (const auto intestine = scene.find("intestine"); intestine != scene.end() && intestine->is_object())
        facts.radius_m = number_or(*intestine, "radius", scene_defaults.radius_m);

    const auto tools = scene.find("tools");
    if (tools == scene.end() || !tools->is_array()) return facts;
    for (const json& tool : *tools) {
        ToolFacts t;
        t.radius_m = number_or(tool, "radius", tool_defaults.radius_m);
        t.length_m = number_or(tool, "length", tool_defaults.length_m);
        t.max_force_N = number_or(tool, "max_force", tool_defaults.max_force_N);
        Eigen::Vector3d position(tool_defaults.position_m[0], tool_defaults.position_m[1], tool_defaults.position_m[2]);
        Eigen::Quaterniond orientation(tool_defaults.orientation_wxyz[0], tool_defaults.orientation_wxyz[1],
                                       tool_defaults.orientation_wxyz[2], tool_defaults.orientation_wxyz[3]);
        if (const auto p = tool.find("position"); p != tool.end() && p->is_array() && p->size() == 3)
            position = Eigen::Vector3d((*p)[0].get<double>(), (*p)[1].get<double>(), (*p)[2].get<double>());
        if (const auto q = tool.find("orientation"); q != tool.end() && q->is_array() && q->size() == 4)
            orientation = Eigen::Quaterniond((*q)[0].get<double>(), (*q)[1].get<double>(), (*q)[2].get<double>(),
                                             (*q)[3].get<double>());
        t.initial_pose.position = position;
        t.initial_pose.orientation = orientation.normalized();
        facts.tools.push_back(t);
    }
    return facts;
}

}  // namespace enteron::bridge
