// SPDX-License-Identifier: Apache-2.0
// ent_scene_desc -> SceneConfig: the C description in C++ terms, effects taken from the
// `effects` bitmask, then checked by the same validate() as JSON, with C field names.
#pragma once

#include "enteron/enteron.h"
#include "scene/scene_config.h"

namespace enteron::capi {

// The caller's description over the defaults: checks struct_size against the released
// sizes, and an older, smaller one gets defaults for the fields it lacks. Read nothing
// from the caller's struct but through this: an old caller's struct ends at its size.
ent_scene_desc complete_desc(const ent_scene_desc& given);

// A complete description (from complete_desc) as a validated SceneConfig.
scene::SceneConfig config_from_desc(const ent_scene_desc& desc);

// A config as a whole current ent_scene_desc: its values, the effects it turns on, the
// defaults of those it leaves off; no arrays (shape points, pins) and no callbacks.
ent_scene_desc desc_from_config(const scene::SceneConfig& config);

// Throw Error(version) unless struct_size is the size of the struct in a released header.
void check_scene_desc_size(uint32_t struct_size);
void check_callbacks_size(uint32_t struct_size);

// The released sizes of ent_callbacks, checked when a scene is created.
void check_callbacks(const ent_callbacks& callbacks);

}  // namespace enteron::capi
