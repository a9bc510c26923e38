// What an ent_scene* points to, shared by the C API files that take a scene.
#pragma once

#include <memory_resource>
#include <optional>

#include "base/logger.h"
#include "base/memory.h"
#include "enteron/enteron.h"
#include "scene/scene.h"

namespace enteron::capi {

// What an ent_scene* points to: the scene and the memory it lives in. The handle itself
// comes from the caller's allocator when one is given. ent_scene itself is never defined,
// so the ABI (abi/) records only an opaque pointer, whatever this struct holds.
struct SceneHandle {
    explicit SceneHandle(const ent_callbacks* callbacks) {
        if (callbacks != nullptr && callbacks->allocate != nullptr) {
            callback_memory.emplace(callbacks->allocate, callbacks->release, callbacks->user_data);
            memory = &*callback_memory;
        }
        if (callbacks != nullptr) logger = Logger(callbacks->log, callbacks->user_data);
    }

    std::optional<CallbackMemoryResource> callback_memory;
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    Logger logger;
    std::optional<scene::Scene> scene;
    ent_callbacks callbacks{};  // kept to release the handle itself
};

inline SceneHandle* handle_of(ent_scene* scene) { return reinterpret_cast<SceneHandle*>(scene); }
inline const SceneHandle* handle_of(const ent_scene* scene) { return reinterpret_cast<const SceneHandle*>(scene); }

// The scene of a non-NULL handle.
inline const scene::Scene& scene_of_handle(const ent_scene* scene) { return *handle_of(scene)->scene; }

}  // namespace enteron::capi
