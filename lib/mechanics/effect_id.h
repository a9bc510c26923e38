// SPDX-License-Identifier: Apache-2.0
// Every effect a scene can name. The numbers are those of ENT_EFFECT_* in enteron.h.
#pragma once

#include <cstddef>

namespace enteron::mechanics {

enum class EffectId : int {
    stretch = 0,
    bend = 1,
    damping = 2,
    gravity = 3,
    mesentery = 4,
    pinned = 5,
    environment = 6,
    self_collision = 7,
    tools = 8,
};

constexpr std::size_t kEffectCount = 9;

// The JSON-style name of an effect ("stretch", ...).
inline const char* effect_name(EffectId id) {
    static const char* const names[kEffectCount] = {"stretch",   "bend",   "damping",    "gravity",
                                                   "mesentery", "pinned", "environment", "self_collision",
                                                   "tools"};
    return names[static_cast<std::size_t>(id)];
}

}  // namespace enteron::mechanics
