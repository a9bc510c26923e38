// SPDX-License-Identifier: Apache-2.0
// The skin entry points of the C API: a skin wraps a lib/skinning skin, the published
// snapshots of its scene (shared: a skin may outlive its scene) and the copy of the axis
// it reads into.
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "capi/call_guard.h"
#include "capi/calls_in_flight.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "scene/checked_value.h"
#include "skinning/skin.h"
#include "skinning/skin_metrics.h"

using enteron::Error;
using enteron::ErrorCode;
using enteron::capi::guarded;
using enteron::capi::require;

namespace {

using enteron::capi::SceneHandle;

// Releases the skin's reference to its scene's handle.
struct SceneReference {
    void operator()(SceneHandle* handle) const { enteron::capi::release(handle); }
};

// What an ent_skin* points to. ent_skin itself is never defined (opaque in the ABI).
struct SkinHandle {
    // The scene's handle, for its published snapshots: they stay as long as the skin does.
    std::unique_ptr<SceneHandle, SceneReference> scene;
    std::unique_ptr<enteron::skinning::Skin> skin;
    std::vector<double> points;  // control points copied from the snapshot
    double time_s = 0.0;
    uint64_t updates = 0;
    uint64_t last_update_ns = 0;
    enteron::capi::CallsInFlight calls;  // on the skin, and its destroy
    std::atomic<bool> busy{false};       // while a call runs: one at a time per skin
};

SkinHandle* handle_of(const ent_skin* skin) { return reinterpret_cast<SkinHandle*>(const_cast<ent_skin*>(skin)); }

// A call on a skin, for as long as it runs: counted in flight (calls_in_flight.h: a destroy
// on another thread leaves the skin to the last call in flight), and alone on its skin. A
// skin belongs to one thread at a time; a call made while another runs on the same skin on
// another thread is refused as busy (it would read the buffers the other rewrites) instead
// of corrupting them. `call` names the entry point, for the messages.
class SkinCall {
public:
    SkinCall(const ent_skin* skin, const char* call) {
        require(skin, "skin");
        handle_ = handle_of(skin);
        if (!handle_->calls.enter())
            throw Error(ErrorCode::invalid_argument, std::string(call) + ": skin was destroyed (ent_skin_destroy)");
        if (handle_->busy.exchange(true, std::memory_order_acquire)) {
            if (handle_->calls.leave()) delete handle_;
            throw Error(ErrorCode::busy, std::string(call) +
                                             ": another thread is in a call on this skin (ent_skin_update, "
                                             "ent_skin_mesh or ent_skin_metrics); a skin is used by one thread at "
                                             "a time. Nothing was done: call again once it has returned");
        }
    }
    ~SkinCall() {
        handle_->busy.store(false, std::memory_order_release);
        if (handle_->calls.leave()) delete handle_;
    }
    SkinCall(const SkinCall&) = delete;
    SkinCall& operator=(const SkinCall&) = delete;

    SkinHandle& handle() const { return *handle_; }

private:
    SkinHandle* handle_;
};

// A knob of the skin description, within [low, high].
template <typename T>
void check_knob(T value, T low, T high, const char* field) {
    enteron::scene::Checked<T>(value, field, ErrorCode::invalid_argument).at_least(low).at_most(high);
}

// The sizes of ent_skin_desc in released headers. An older size is the offset of the first
// field its header lacks; those fields take their defaults.
//   0.1 first skins  without ring_chord_error_radii.
//   0.1 skins' LOD   without stable_topology.
//   0.1              without contact_surfaces and skeleton_chord_error_radii.
//   the current header.
void check_skin_desc_size(uint32_t struct_size) {
    enteron::capi::check_struct_size(struct_size,
                                     {offsetof(ent_skin_desc, ring_chord_error_radii),
                                      offsetof(ent_skin_desc, stable_topology),
                                      offsetof(ent_skin_desc, contact_surfaces), sizeof(ent_skin_desc)},
                                     "ent_skin_desc");
}

// The sizes of ent_mesh_view: without around_v and what follows it, and now.
void check_mesh_view_size(uint32_t struct_size) {
    enteron::capi::check_struct_size(struct_size, {offsetof(ent_mesh_view, around_v), sizeof(ent_mesh_view)},
                                     "ent_mesh_view");
}

// The sizes of ent_skin_metrics: without facet_error_rms and facet_error_max, without the
// contact and motion measures (overlap_depth_max and what follows), and now.
void check_skin_metrics_size(uint32_t struct_size) {
    enteron::capi::check_struct_size(struct_size,
                                     {offsetof(struct ent_skin_metrics, facet_error_rms),
                                      offsetof(struct ent_skin_metrics, overlap_depth_max),
                                      sizeof(struct ent_skin_metrics)},
                                     "ent_skin_metrics");
}

// The radius along the scene's tube, for its skins (tube_radius.h): the profile (a copy:
// the skin may outlive the scene) at rest arc length s = p l0, or constant.
enteron::skinning::TubeRadius radius_along(const enteron::scene::Scene& scene) {
    enteron::skinning::TubeRadius along;
    if (scene.radius_profile().empty()) return along;
    along.profile = std::make_shared<const enteron::spline::LengthProfile>(scene.radius_profile());
    along.segment_rest_length = scene.rest_length() / static_cast<double>(scene.control_points() - 1);
    return along;
}

ent_skin_desc default_skin_desc() {
    ent_skin_desc defaults{};
    defaults.struct_size = sizeof defaults;
    defaults.method = ENT_SKIN_CONVOLUTION;
    defaults.segments = 16;
    defaults.ring_spacing_radii = 0.5;
    defaults.cap_rings = 4;
    defaults.skeleton_spacing_radii = 0.25;
    defaults.voxel_size_radii = 1.0 / 3.0;
    defaults.window_radii = 1.0;
    defaults.ring_chord_error_radii = 0.0;
    defaults.stable_topology = 1;
    defaults.contact_surfaces = 1;
    defaults.skeleton_chord_error_radii = 0.0;
    return defaults;
}

enteron::skinning::SkinSettings settings_from_desc(const ent_skin_desc& given, double radius) {
    check_skin_desc_size(given.struct_size);
    // An older caller's smaller struct: the fields it lacks keep their defaults.
    ent_skin_desc desc = default_skin_desc();
    std::memcpy(&desc, &given, given.struct_size);
    if (desc.method != ENT_SKIN_TUBE && desc.method != ENT_SKIN_POINT_SKELETON && desc.method != ENT_SKIN_CONVOLUTION)
        throw Error(ErrorCode::invalid_argument,
                    "method must be ENT_SKIN_TUBE, ENT_SKIN_POINT_SKELETON or ENT_SKIN_CONVOLUTION (0, 1, 2), got " +
                        std::to_string(desc.method));
    check_knob(desc.segments, 3u, 1024u, "segments");
    check_knob(desc.ring_spacing_radii, 0.05, 8.0, "ring_spacing_radii");
    check_knob(desc.cap_rings, 0u, 64u, "cap_rings");
    check_knob(desc.skeleton_spacing_radii, 0.05, 2.0, "skeleton_spacing_radii");
    check_knob(desc.voxel_size_radii, 0.1, 2.0, "voxel_size_radii");
    // The window must stay below 2 R, where folds would blend.
    enteron::scene::Checked<double>(desc.window_radii, "window_radii", ErrorCode::invalid_argument)
        .at_least(0.25)
        .below(2.0);
    check_knob(desc.ring_chord_error_radii, 0.0, 1.0, "ring_chord_error_radii");
    check_knob(desc.stable_topology, 0, 1, "stable_topology");
    check_knob(desc.contact_surfaces, 0, 1, "contact_surfaces");
    check_knob(desc.skeleton_chord_error_radii, 0.0, 0.1, "skeleton_chord_error_radii");
    enteron::skinning::SkinSettings s;
    s.method = static_cast<enteron::skinning::SkinMethod>(desc.method);
    s.radius = radius;
    s.segments = desc.segments;
    s.ring_spacing = desc.ring_spacing_radii * radius;
    s.cap_rings = desc.cap_rings;
    s.skeleton_spacing = desc.skeleton_spacing_radii * radius;
    s.voxel_size = desc.voxel_size_radii * radius;
    s.window = desc.window_radii * radius;
    s.ring_chord_error = desc.ring_chord_error_radii * radius;
    s.stable_topology = desc.stable_topology != 0;
    s.contact_surfaces = desc.contact_surfaces != 0;
    s.skeleton_chord_error = desc.skeleton_chord_error_radii * radius;
    return s;
}

}  // namespace

extern "C" {

ENT_API ent_status ent_skin_desc_init(ent_skin_desc* desc, uint32_t struct_size) {
    return guarded([&] {
        require(desc, "desc");
        check_skin_desc_size(struct_size);
        ent_skin_desc defaults = default_skin_desc();
        defaults.struct_size = struct_size;
        // An older caller's struct ends at struct_size: write nothing past it.
        std::memcpy(desc, &defaults, struct_size);
    });
}

ENT_API ent_status ent_skin_create(ent_scene* scene, const ent_skin_desc* desc, ent_skin** out_skin) {
    return guarded([&] {
        const enteron::capi::SceneCall call(scene);
        SceneHandle& scene_handle = call.handle();
        require(desc, "desc");
        require(out_skin, "out_skin");
        const enteron::scene::Scene& s = *scene_handle.scene;
        enteron::skinning::SkinSettings settings = settings_from_desc(*desc, s.radius());
        // The knobs scale with the largest radius; the skin draws the profile's at each place.
        settings.radius_along = radius_along(s);
        auto handle = std::make_unique<SkinHandle>();
        handle->skin = enteron::skinning::make_skin(settings);
        handle->points.resize(3 * s.control_points());
        enteron::capi::retain(scene_handle);
        handle->scene.reset(&scene_handle);
        *out_skin = reinterpret_cast<ent_skin*>(handle.release());
    });
}

ENT_API ent_status ent_skin_update(ent_skin* skin) {
    return guarded([&] {
        const SkinCall call(skin, "ent_skin_update");
        SkinHandle& h = call.handle();
        const auto start = std::chrono::steady_clock::now();
        {
            // Pin the snapshot only for the copy: the stepping thread keeps publishing.
            const enteron::scene::SnapshotPublisher::Reader snapshot(*h.scene->published);
            std::memcpy(h.points.data(), snapshot->control_points.data(), h.points.size() * sizeof(double));
            h.time_s = snapshot->stats.time;
        }
        h.skin->update(h.points.data(), h.points.size() / 3);
        h.updates += 1;
        h.last_update_ns = static_cast<uint64_t>(
            std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count());
    });
}

ENT_API ent_status ent_skin_mesh(const ent_skin* skin, ent_mesh_view* out) {
    return guarded([&] {
        const SkinCall call(skin, "ent_skin_mesh");
        require(out, "out");
        check_mesh_view_size(out->struct_size);
        const SkinHandle& h = call.handle();
        const enteron::skinning::Skin& sk = *h.skin;
        const enteron::skinning::Mesh& mesh = sk.mesh();
        ent_mesh_view full{};
        full.struct_size = out->struct_size;
        const bool empty = h.updates == 0 || mesh.vertex_count() == 0;
        full.vertex_count = empty ? 0 : static_cast<uint32_t>(mesh.vertex_count());
        full.triangle_count = empty ? 0 : static_cast<uint32_t>(mesh.triangle_count());
        full.positions_xyz_m = empty ? nullptr : mesh.positions.data();
        full.normals_xyz = empty ? nullptr : mesh.normals.data();
        full.axis_u = empty ? nullptr : mesh.u.data();
        full.indices = empty ? nullptr : mesh.indices.data();
        full.time_s = h.time_s;
        full.updates = h.updates;
        full.around_v = empty ? nullptr : mesh.v.data();
        full.tangents_xyz = empty ? nullptr : mesh.tangents.data();
        full.topology_serial = sk.topology_changes();
        full.topology_changed = h.updates > 0 && sk.topology_changed() ? 1 : 0;
        full.stable_topology = sk.stable_topology() ? 1 : 0;
        std::memcpy(out, &full, out->struct_size);
    });
}

ENT_API ent_status ent_skin_metrics(const ent_skin* skin, struct ent_skin_metrics* out) {
    return guarded([&] {
        const SkinCall call(skin, "ent_skin_metrics");
        require(out, "out");
        check_skin_metrics_size(out->struct_size);
        const SkinHandle& h = call.handle();
        struct ent_skin_metrics full{};
        full.struct_size = out->struct_size;
        if (h.updates > 0) {
            const auto& sk = *h.skin;
            enteron::skinning::PreviousFrame previous;
            if (sk.has_previous()) {
                previous.mesh = &sk.previous_mesh();
                previous.points_xyz = sk.previous_axis_points();
                previous.count = sk.previous_axis_count();
                previous.table = &sk.previous_arc_length();
            }
            const enteron::skinning::SkinMetrics m =
                enteron::skinning::measure_skin(sk.mesh(), sk.axis_points(), sk.axis_count(), sk.arc_length(),
                                                sk.settings().radius, sk.settings().radius_along,
                                                sk.has_previous() ? &previous : nullptr);
            full.vertex_count = static_cast<uint32_t>(m.vertices);
            full.triangle_count = static_cast<uint32_t>(m.triangles);
            full.watertight = m.watertight ? 1 : 0;
            full.open_edges = static_cast<uint32_t>(m.open_edges);
            full.nonmanifold_edges = static_cast<uint32_t>(m.nonmanifold_edges);
            full.blended_vertices = static_cast<uint32_t>(m.blended_vertices);
            full.inverted_triangles = static_cast<uint32_t>(m.inverted_triangles);
            full.radius_error_rms = m.radius_error_rms;
            full.radius_error_max = m.radius_error_max;
            full.facet_error_rms = m.facet_error_rms;
            full.facet_error_max = m.facet_error_max;
            full.normal_deviation_rms_rad = m.normal_deviation_rms;
            full.normal_deviation_max_rad = m.normal_deviation_max;
            full.volume_m3 = m.volume;
            full.volume_error = m.volume_error;
            full.axis_length_m = m.axis_length;
            full.overlap_depth_max = m.overlap_depth_max;
            full.overlap_area_m2 = m.overlap_area;
            full.tube_overlap_depth_max = m.tube_overlap_depth_max;
            full.tube_overlap_area_m2 = m.tube_overlap_area;
            full.contact_gap_max = m.contact_gap_max;
            full.shape_volume_error = m.shape_volume_error;
            full.free_radius_error_rms = m.free_radius_error_rms;
            full.vertex_motion_max = m.vertex_motion_max;
            full.vertex_excess_motion_max = m.vertex_excess_motion_max;
            full.free_vertex_count = static_cast<uint32_t>(m.free_vertices);
            full.has_previous_update = sk.has_previous() ? 1 : 0;
        }
        full.last_update_ns = h.last_update_ns;
        std::memcpy(out, &full, out->struct_size);
    });
}

ENT_API void ent_skin_destroy(ent_skin* skin) {
    if (skin == nullptr) return;
    SkinHandle* handle = handle_of(skin);
    // With calls still in flight on other threads, the last of them deletes it as it returns.
    if (handle->calls.destroy()) delete handle;
}

}  // extern "C"
