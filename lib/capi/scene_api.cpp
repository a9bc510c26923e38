// SPDX-License-Identifier: Apache-2.0
// The scene entry points of the C API: create, destroy, step and the snapshot queries.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory_resource>
#include <optional>
#include <string>

#include "base/memory.h"
#include "capi/call_guard.h"
#include "capi/driving_call.h"
#include "capi/scene_desc.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "scene/json_loader.h"
#include "scene/plausible_ranges.h"
#include "scene/scene.h"
#include "spline/arc_length.h"

using enteron::Error;
using enteron::ErrorCode;
using enteron::capi::guarded;
using enteron::capi::require;

namespace {

using enteron::capi::SceneHandle;
using enteron::capi::handle_of;
using enteron::capi::SceneCall;

// A validated config as a scene, after the warnings of the values no abdomen has.
ent_scene* make_handle(const ent_callbacks* callbacks, const enteron::scene::SceneConfig& config,
                       const enteron::scene::FieldNames& names) {
    if (callbacks != nullptr) enteron::capi::check_callbacks(*callbacks);
    const bool custom = callbacks != nullptr && callbacks->allocate != nullptr;
    void* memory = custom ? callbacks->allocate(callbacks->user_data, sizeof(SceneHandle), alignof(SceneHandle))
                          : ::operator new(sizeof(SceneHandle), std::nothrow);
    if (memory == nullptr) throw std::bad_alloc();
    SceneHandle* handle = nullptr;
    try {
        handle = new (memory) SceneHandle(callbacks, config.intestine.control_points, enteron::scene::spline_ends(config));
    } catch (...) {
        if (custom)
            callbacks->release(callbacks->user_data, memory, sizeof(SceneHandle), alignof(SceneHandle));
        else
            ::operator delete(memory);
        throw;
    }
    try {
        enteron::scene::warn_implausible(config, names, handle->logger);
        handle->description = enteron::capi::desc_from_config(config);
        handle->scene.emplace(config, *handle->published, handle->memory, handle->logger, names);
    } catch (...) {
        enteron::capi::release(handle);
        throw;
    }
    return reinterpret_cast<ent_scene*>(handle);
}

}  // namespace

namespace enteron::capi {

void release(SceneHandle* handle) {
    if (handle->references.fetch_sub(1, std::memory_order_acq_rel) != 1) return;
    const ent_callbacks callbacks = handle->callbacks;
    handle->~SceneHandle();
    if (callbacks.release != nullptr)
        callbacks.release(callbacks.user_data, handle, sizeof(SceneHandle), alignof(SceneHandle));
    else
        ::operator delete(handle);
}

void destroy_scene(SceneHandle* handle) noexcept {
    handle->scene.reset();
    release(handle);
}

}  // namespace enteron::capi

extern "C" {

ENT_API ent_status ent_scene_create(const ent_scene_desc* desc, ent_scene** out_scene) {
    return guarded([&] {
        require(desc, "desc");
        require(out_scene, "out_scene");
        const ent_scene_desc complete = enteron::capi::complete_desc(*desc);
        const enteron::scene::SceneConfig config = enteron::capi::config_from_desc(complete);
        *out_scene = make_handle(complete.callbacks, config, enteron::scene::c_field_names());
    });
}

ENT_API ent_status ent_scene_create_json_with(const char* json, size_t length, const ent_callbacks* callbacks,
                                              ent_scene** out_scene) {
    return guarded([&] {
        require(json, "json");
        require(out_scene, "out_scene");
        const enteron::scene::SceneConfig config = enteron::scene::load_scene_json(json, length);
        *out_scene = make_handle(callbacks, config, enteron::scene::json_field_names());
    });
}

ENT_API ent_status ent_scene_create_json_file(const char* path, const ent_callbacks* callbacks, ent_scene** out_scene) {
    return guarded([&] {
        require(path, "path");
        require(out_scene, "out_scene");
        std::ifstream file(path, std::ios::binary);
        if (!file) throw Error(ErrorCode::invalid_argument, std::string("path \"") + path + "\" cannot be opened");
        const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        if (file.bad()) throw Error(ErrorCode::invalid_argument, std::string("path \"") + path + "\" cannot be read");
        const std::string name(path);
        const std::size_t slash = name.find_last_of('/');
        const std::string directory = slash == std::string::npos ? "" : slash == 0 ? "/" : name.substr(0, slash);
        const enteron::scene::SceneConfig config = enteron::scene::load_scene_json(text.data(), text.size(), directory);
        *out_scene = make_handle(callbacks, config, enteron::scene::json_field_names());
    });
}

ENT_API ent_status ent_scene_create_json(const char* json, size_t length, ent_scene** out_scene) {
    return ent_scene_create_json_with(json, length, nullptr, out_scene);
}

ENT_API void ent_scene_destroy(ent_scene* scene) {
    if (scene == nullptr) return;
    SceneHandle* handle = handle_of(scene);
    // With calls still in flight on other threads, the last of them destroys it as it returns.
    if (handle->calls.destroy()) enteron::capi::destroy_scene(handle);
}

ENT_API ent_status ent_scene_step(ent_scene* scene, double dt_s) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        const enteron::capi::DrivingCall driving(handle, "ent_scene_step");
        handle.scene->step(dt_s);
    });
}

namespace {
// Samples tube `tube` of the last published axis evenly in arc length (ent_scene_axis,
// ent_scene_intestine_axis).
void sample_published_tube(const SceneHandle& handle, std::size_t tube, std::size_t count, double* points_xyz_m) {
    const enteron::scene::PublishedTube& published = handle.published->tube(tube);
    const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
    enteron::spline::sample_evenly(snapshot->control_points.data() + 3 * published.first, published.control_points,
                                   count, points_xyz_m, published.ends);
}
}  // namespace

ENT_API ent_status ent_scene_axis(const ent_scene* scene, uint32_t count, double* points_xyz_m) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(points_xyz_m, "points_xyz_m");
        if (count < 2) throw Error(ErrorCode::invalid_argument, "count must be >= 2, got " + std::to_string(count));
        sample_published_tube(handle, 0, count, points_xyz_m);
    });
}

ENT_API ent_status ent_scene_intestine_count(const ent_scene* scene, int32_t* count) {
    return guarded([&] {
        const SceneCall call(scene);
        require(count, "count");
        *count = static_cast<int32_t>(call.handle().published->tube_count());
    });
}

ENT_API ent_status ent_scene_intestine_axis(const ent_scene* scene, int32_t intestine, size_t count,
                                            double* points_xyz_m) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(points_xyz_m, "points_xyz_m");
        const std::size_t tubes = handle.published->tube_count();
        if (intestine < 0 || static_cast<std::size_t>(intestine) >= tubes)
            throw Error(ErrorCode::invalid_argument, "intestine must be in [0, " + std::to_string(tubes) +
                                                         "): the scene has " + std::to_string(tubes) +
                                                         (tubes == 1 ? " intestine" : " intestines") + ", got " +
                                                         std::to_string(intestine));
        // As ent_scene_axis's uint32_t count: a count the 32-bit call could not take is a mistake.
        if (count < 2 || count > UINT32_MAX)
            throw Error(ErrorCode::invalid_argument,
                        "count must be in [2, 4294967295], got " + std::to_string(count));
        sample_published_tube(handle, static_cast<std::size_t>(intestine), count, points_xyz_m);
    });
}

ENT_API ent_status ent_scene_control_points(const ent_scene* scene, uint32_t capacity, double* points_xyz_m,
                                            uint32_t* out_count) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out_count, "out_count");
        // The first intestine's (enteron.h).
        const enteron::scene::PublishedTube& tube = handle.published->tube(0);
        const uint32_t count = static_cast<uint32_t>(tube.control_points);
        if (points_xyz_m != nullptr && capacity < count) {
            *out_count = count;
            throw Error(ErrorCode::buffer_too_small, "capacity is " + std::to_string(capacity) +
                                                         " points, the scene has " + std::to_string(count));
        }
        *out_count = count;
        if (points_xyz_m == nullptr) return;
        const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
        const auto first = snapshot->control_points.begin() + static_cast<std::ptrdiff_t>(3 * tube.first);
        std::copy(first, first + static_cast<std::ptrdiff_t>(3 * tube.control_points), points_xyz_m);
    });
}

ENT_API ent_status ent_scene_stats(const ent_scene* scene, ent_stats* out) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out, "out");
        // The sizes of ent_stats in released headers; fields past an older size are not
        // written. 0.0 preview: without last_step_ns (a simulated release, see
        // complete_desc in scene_desc.cpp and tests/abi/); 0.1: up to last_step_ns; then the
        // current header, with what a slow step did.
        enteron::capi::check_struct_size(out->struct_size,
                                         {offsetof(ent_stats, last_step_ns), offsetof(ent_stats, last_step_attempts),
                                          sizeof(ent_stats)},
                                         "ent_stats");
        const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
        const enteron::scene::SceneStats& stats = snapshot->stats;
        ent_stats full{};
        full.struct_size = out->struct_size;
        full.control_points = static_cast<uint32_t>(handle.published->control_points());
        full.time_s = stats.time;
        full.steps = stats.steps;
        full.substeps = stats.substeps;
        full.rollbacks = stats.rollbacks;
        full.kinetic_energy_J = stats.kinetic_energy;
        full.potential_energy_J = stats.potential_energy;
        full.contacts = stats.contacts;
        full.max_penetration_m = stats.max_penetration;
        full.last_step_ns = stats.last_step_ns;
        full.last_step_attempts = stats.last_step_attempts;
        full.last_step_substeps = stats.last_step_substeps;
        full.last_step_proxy_iterations = stats.work.proxy_iterations;
        full.last_step_proxy_evaluations = stats.work.proxy_evaluations;
        full.max_step_ns = stats.max_step_ns;
        full.late_steps = stats.late_steps;
        full.subdivided_steps = stats.subdivided_steps;
        full.proxy_unbalanced_solves = stats.work.proxy_unbalanced;
        full.full_contact_searches = stats.work.full_contact_searches;
        std::memcpy(out, &full, out->struct_size);
    });
}

ENT_API ent_status ent_scene_effect_stats(const ent_scene* scene, int32_t effect, ent_effect_stats* out) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out, "out");
        enteron::capi::check_struct_size(out->struct_size, {sizeof(ent_effect_stats)}, "ent_effect_stats");
        if (effect < 0 || effect >= ENT_EFFECT_COUNT)
            throw Error(ErrorCode::not_found, "effect " + std::to_string(effect) + " is not an ENT_EFFECT_* this library knows");
        const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
        const enteron::scene::EffectStats& stats = snapshot->effects[static_cast<std::size_t>(effect)];
        ent_effect_stats full{};
        full.struct_size = out->struct_size;
        full.enabled = stats.enabled ? 1 : 0;
        full.calls = stats.calls;
        full.total_time_ns = stats.total_time_ns;
        std::memcpy(out, &full, out->struct_size);
    });
}

}  // extern "C"
