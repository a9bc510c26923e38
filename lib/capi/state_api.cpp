// SPDX-License-Identifier: Apache-2.0
// Save and restore through the C API (docs/scoring-and-state.md): driving calls, since they read
// or replace the live state of the scene, not a snapshot.
#include <string>

#include "capi/call_guard.h"
#include "capi/driving_call.h"
#include "capi/scene_handle.h"

using enteron::Error;
using enteron::ErrorCode;
using enteron::capi::guarded;
using enteron::capi::SceneCall;
using enteron::capi::require;

extern "C" {

ENT_API ent_status ent_scene_save_state(ent_scene* scene, void* buffer, size_t capacity, size_t* out_size) {
    return guarded([&] {
        const SceneCall call(scene);
        enteron::capi::SceneHandle& handle = call.handle();
        require(out_size, "out_size");
        const enteron::capi::DrivingCall driving(handle, "ent_scene_save_state");
        // Measured first: a buffer too small receives nothing.
        const std::size_t size = handle.scene->save_state(nullptr, 0);
        *out_size = size;
        if (buffer == nullptr) return;
        if (capacity < size)
            throw Error(ErrorCode::buffer_too_small, "capacity is " + std::to_string(capacity) +
                                                         " bytes, the state needs " + std::to_string(size));
        handle.scene->save_state(buffer, capacity);
    });
}

ENT_API ent_status ent_scene_restore_state(ent_scene* scene, const void* buffer, size_t size) {
    return guarded([&] {
        const SceneCall call(scene);
        enteron::capi::SceneHandle& handle = call.handle();
        require(buffer, "buffer");
        const enteron::capi::DrivingCall driving(handle, "ent_scene_restore_state");
        handle.scene->restore_state(buffer, size);
    });
}

}  // extern "C"
