// SPDX-License-Identifier: Apache-2.0
// What a saved state belongs to (ent_scene_save_state, docs/scoring-and-state.md): a hash of
// every value of a scene's description that its state and its physics depend on. A state
// restores only into a scene with the same fingerprint: one made from the same
// description, with the same obstacles and tools added in the same order.
//
// A field added to SceneConfig (or to an obstacle or a tool) that changes the physics is
// added here too; one left out only lets a state restore into a scene that differs in it.
#pragma once

#include "base/state_io.h"
#include "collision/obstacle.h"
#include "collision/tool.h"
#include "scene/scene_config.h"

namespace enteron::scene {

// Adds the description (intestine, start shape, solver, effects and their settings, the
// obstacles and tools it lists).
void add_to_fingerprint(Fingerprint& fingerprint, const SceneConfig& config);
// Adds an obstacle or a tool added after creation.
void add_to_fingerprint(Fingerprint& fingerprint, const collision::Obstacle& obstacle);
void add_to_fingerprint(Fingerprint& fingerprint, const collision::ToolConfig& tool);

}  // namespace enteron::scene
