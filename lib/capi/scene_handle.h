// What an ent_scene* points to, shared by the C API files that take a scene.
#pragma once

#include <atomic>
#include <memory_resource>
#include <optional>

#include "base/logger.h"
#include "base/memory.h"
#include "capi/call_guard.h"
#include "enteron/enteron.h"
#include "scene/scene.h"
#include "scene/snapshot.h"

namespace enteron::capi {

// What an ent_scene* points to: the scene, the snapshots it publishes, and the memory they
// live in. The handle itself comes from the caller's allocator when one is given.
// ent_scene itself is never defined, so the ABI (abi/) records only an opaque pointer,
// whatever this struct holds.
//
// Lifetimes: ent_scene_destroy destroys the scene at once, but its skins share the
// published snapshots (each holds a reference), so a skin that outlives its scene keeps
// working on the last published state; the handle goes with its last reference.
struct SceneHandle {
    SceneHandle(const ent_callbacks* callbacks, std::size_t control_points, spline::Ends ends) {
        if (callbacks != nullptr && callbacks->allocate != nullptr) {
            callback_memory.emplace(callbacks->allocate, callbacks->release, callbacks->user_data);
            memory = &*callback_memory;
        }
        if (callbacks != nullptr) logger = Logger(callbacks->log, callbacks->user_data);
        if (callbacks != nullptr) this->callbacks = *callbacks;
        published.emplace(3 * control_points, memory, ends);
    }

    std::optional<CallbackMemoryResource> callback_memory;
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    Logger logger;
    ent_callbacks callbacks{};  // kept to release the handle itself
    ent_scene_desc description{};  // what the scene was made from (ent_scene_read_desc), set before it is shared
    std::optional<scene::SnapshotPublisher> published;  // outlives scene, for the skins
    std::optional<scene::Scene> scene;                  // reset by ent_scene_destroy
    std::atomic<uint32_t> references{1};                // the scene's, and one per skin
    std::atomic<bool> driving{false};                   // while a driving call runs (driving_call.h)
};

inline SceneHandle* handle_of(ent_scene* scene) { return reinterpret_cast<SceneHandle*>(scene); }
inline const SceneHandle* handle_of(const ent_scene* scene) { return reinterpret_cast<const SceneHandle*>(scene); }

// Adds a reference to the handle (a skin's), from any thread.
inline void retain(SceneHandle& handle) { handle.references.fetch_add(1, std::memory_order_relaxed); }
// Drops a reference; the last one destroys the handle and releases its memory.
void release(SceneHandle* handle);

// The handle of a scene argument. NULL is refused, and so is a destroyed scene whose skins
// keep its handle alive (a scene destroyed without skins is gone: using it is the
// caller's dangling pointer).
inline SceneHandle& live_handle(ent_scene* scene) {
    require(scene, "scene");
    SceneHandle& handle = *handle_of(scene);
    if (!handle.scene) throw Error(ErrorCode::invalid_argument, "scene was destroyed (ent_scene_destroy)");
    return handle;
}
inline const SceneHandle& live_handle(const ent_scene* scene) { return live_handle(const_cast<ent_scene*>(scene)); }

}  // namespace enteron::capi
