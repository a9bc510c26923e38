// SPDX-License-Identifier: Apache-2.0
// What an ent_scene* points to, shared by the C API files that take a scene.
#pragma once

#include <atomic>
#include <memory_resource>
#include <optional>

#include "base/logger.h"
#include "base/memory.h"
#include "capi/call_guard.h"
#include "capi/calls_in_flight.h"
#include "enteron/enteron.h"
#include "scene/scene.h"
#include "scene/snapshot.h"

namespace enteron::capi {

// What an ent_scene* points to: the scene, the snapshots it publishes, and the memory they
// live in. The handle itself comes from the caller's allocator when one is given.
// ent_scene itself is never defined, so the ABI (abi/) records only an opaque pointer,
// whatever this struct holds.
//
// Lifetimes: ent_scene_destroy destroys the scene, at once or, when calls on it are still
// running on other threads, as the last of them returns (calls_in_flight.h). Its skins
// share the published snapshots (each holds a reference), so a skin that outlives its
// scene keeps working on the last published state; the handle goes with its last reference.
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
    std::optional<scene::Scene> scene;                  // reset by destroy_scene
    CallsInFlight calls;                                // on the scene, and its destroy
    std::atomic<uint32_t> references{1};                // the scene's, and one per skin
    std::atomic<bool> driving{false};                   // while a driving call runs (driving_call.h)
};

inline SceneHandle* handle_of(ent_scene* scene) { return reinterpret_cast<SceneHandle*>(scene); }
inline const SceneHandle* handle_of(const ent_scene* scene) { return reinterpret_cast<const SceneHandle*>(scene); }

// Adds a reference to the handle (a skin's), from any thread.
inline void retain(SceneHandle& handle) { handle.references.fetch_add(1, std::memory_order_relaxed); }
// Drops a reference; the last one destroys the handle and releases its memory.
void release(SceneHandle* handle);

// Destroys the scene and drops its reference to the handle: by ent_scene_destroy, or by the
// last call in flight when the destroy came while it ran.
void destroy_scene(SceneHandle* handle) noexcept;

// A call on a scene, for as long as it runs (every entry point that takes an ent_scene*):
// counted in flight, so that a destroy on another thread leaves the scene to it, and the
// scene goes as the last such call returns. NULL is refused, and so is a scene already destroyed whose handle is still
// there (its skins keep it, or another call is in flight); a scene destroyed without skins
// or calls in flight is gone: using it is the caller's dangling pointer.
class SceneCall {
public:
    explicit SceneCall(const ent_scene* scene) {
        require(scene, "scene");
        handle_ = handle_of(const_cast<ent_scene*>(scene));
        if (!handle_->calls.enter())
            throw Error(ErrorCode::invalid_argument, "scene was destroyed (ent_scene_destroy)");
    }
    ~SceneCall() {
        if (handle_->calls.leave()) destroy_scene(handle_);
    }
    SceneCall(const SceneCall&) = delete;
    SceneCall& operator=(const SceneCall&) = delete;

    SceneHandle& handle() const { return *handle_; }

private:
    SceneHandle* handle_;
};

}  // namespace enteron::capi
