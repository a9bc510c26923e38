// SPDX-License-Identifier: Apache-2.0
// Prints the keys of the scene description's table (lib/scene/scene_table.h) as JSON, one
// entry per object of a JSON scene, named by its path ("" the top level, "intestine.shape",
// "environment" for every obstacle, "tools" for every tool):
//   {"intestine.shape": {"keys": ["kind", "center", ...], "choices": {"kind": ["line", ...]}}, ...}
// check_docs.py json_keys reads it to check that docs/scene-json.md documents every row.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_table.h"

namespace {

using enteron::scene::Block;
using enteron::scene::Choice;
using enteron::scene::Field;
using enteron::scene::List;
using enteron::scene::Object;
using nlohmann::json;

void print_block(const Block& block, const std::string& path, json& out) {
    json& entry = out[path];
    entry["keys"] = json::array();
    entry["choices"] = json::object();
    for (const Field& field : block) {
        entry["keys"].push_back(field.key);
        const std::string inner = path.empty() ? field.key : path + "." + field.key;
        if (const Choice* choice = std::get_if<Choice>(&field.value)) {
            json names = json::array();
            for (std::size_t i = 0; i < choice->choices.count; ++i) names.push_back(choice->choices.names[i].name);
            entry["choices"][field.key] = names;
        } else if (const Object* object = std::get_if<Object>(&field.value)) {
            print_block(*object->block, inner, out);
        } else if (const List* list = std::get_if<List>(&field.value)) {
            print_block(*list->block, inner, out);
        }
    }
}

}  // namespace

int main() {
    json out = json::object();
    print_block(enteron::scene::scene_block(), "", out);
    std::printf("%s\n", out.dump(1).c_str());
    return 0;
}
