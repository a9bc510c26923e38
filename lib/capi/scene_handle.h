// What other C API files need of an ent_scene*: the scene inside it (scene_api.cpp owns
// the handle's layout).
#pragma once

#include "enteron/enteron.h"
#include "scene/scene.h"

namespace enteron::capi {

// The scene of a non-NULL handle.
const scene::Scene& scene_of_handle(const ent_scene* scene);

}  // namespace enteron::capi
