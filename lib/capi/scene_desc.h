// ent_scene_desc -> SceneConfig: the C description in C++ terms, effects taken from the
// `effects` bitmask, then checked by the same validate() as JSON, with C field names.
#pragma once

#include "enteron/enteron.h"
#include "scene/scene_config.h"

namespace enteron::capi {

scene::SceneConfig config_from_desc(const ent_scene_desc& desc);

// The released sizes of ent_callbacks, checked when a scene is created.
void check_callbacks(const ent_callbacks& callbacks);

}  // namespace enteron::capi
