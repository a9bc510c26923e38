// SPDX-License-Identifier: Apache-2.0
// The settings of a bridge: ent_lcm_bridge_desc with its defaults, checked field by field
// (a message naming the field and the value), and owned (the desc's strings are not kept).
#pragma once

#include <cstdint>
#include <string>

#include "enteron/enteron_lcm.h"
#include "lcm/tool_safety.h"
#include "lcm/workspace_mapping.h"

namespace enteron::lcm {

struct BridgeSettings {
    std::string scene_json;
    bool has_callbacks = false;
    ent_callbacks callbacks{};
    bool network = true;             // lcm_url was not ""
    std::string lcm_url;
    std::string channel_suffix;
    std::string journal_path;        // "": no journal
    ent_lcm_bridge_desc desc{};      // every number as given (the session repeats them)
    WorkspaceMapping mapping;

    // The limits every tool shares (tool_max_force_N is the tool's own).
    SafetyLimits limits() const;
};

// The defaults of ent_lcm_bridge_desc (the full, current struct).
ent_lcm_bridge_desc default_bridge_desc();

// Throws Error(invalid_argument) or Error(version) naming the field.
BridgeSettings bridge_settings(const ent_lcm_bridge_desc& desc);

}  // namespace enteron::lcm
