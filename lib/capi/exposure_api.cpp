// SPDX-License-Identifier: Apache-2.0
// The exposure entry points of the C API: a target prepared once (its sample points,
// weights and the query's work space), then measured against the bowel of the last
// published snapshot from any thread, allocating nothing (collision/tube_occlusion.h has
// the geometry).
#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "base/geometry.h"
#include "capi/call_guard.h"
#include "capi/driving_call.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "collision/tube_occlusion.h"
#include "mechanics/rigid_frames.h"
#include "scene/checked_value.h"
#include "spline/catmull_rom.h"

namespace {

using enteron::Error;
using enteron::ErrorCode;
using enteron::Vec3;
using enteron::capi::SceneHandle;
using enteron::capi::guarded;
using enteron::capi::require;
using enteron::scene::Checked;

constexpr uint32_t kMostPoints = 1u << 20;
constexpr uint32_t kMostTriangles = 1u << 20;
constexpr uint64_t kMostSamples = 1u << 20;  // sight lines of one target

// What an ent_exposure* points to.
struct ExposureHandle {
    const void* scene = nullptr;       // the scene it was made for (compared, never used)
    std::size_t control_points = 0;    // of that scene's bowel
    enteron::spline::Ends ends;        // its spline's end treatment
    uint32_t chords_per_segment = 4;
    int32_t obstacle = ENT_NO_OBSTACLE;  // the target's frame
    std::size_t elements = 0;          // points, or triangles of a patch
    std::vector<std::size_t> element_first;  // element e owns samples [element_first[e], element_first[e + 1])
    std::vector<double> local_samples;  // x y z per sample, in the target's frame
    std::vector<double> weights;        // per sample
    std::vector<double> world_samples;  // x y z per sample, where they are at the query
    enteron::collision::TubeOcclusion occlusion;
    std::atomic<bool> measuring{false};  // a query runs (one thread at a time)
};

ExposureHandle& handle_of(ent_exposure* exposure) {
    require(exposure, "exposure");
    return *reinterpret_cast<ExposureHandle*>(exposure);
}

ent_exposure_desc default_exposure_desc() {
    ent_exposure_desc desc{};
    desc.struct_size = sizeof(ent_exposure_desc);
    desc.samples_per_edge = 4;
    desc.obstacle = ENT_NO_OBSTACLE;
    desc.axis_chords_per_segment = 4;
    return desc;
}

Vec3 point_of(const double* xyz, std::size_t i) { return Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); }

void append(std::vector<double>& xyz, const Vec3& p) { xyz.insert(xyz.end(), {p.x(), p.y(), p.z()}); }

// The target's samples: the points, or each triangle's n^2 sub-triangle centroids (n =
// samples_per_edge), each with its share of the triangle's weight (area x given weight).
void sample_target(const ent_exposure_desc& desc, ExposureHandle& h) {
    const bool patch = desc.triangles != nullptr;
    h.elements = patch ? desc.triangle_count : desc.point_count;
    h.element_first.reserve(h.elements + 1);
    if (!patch) {
        h.local_samples.assign(desc.points_xyz_m, desc.points_xyz_m + 3 * std::size_t{desc.point_count});
        for (std::size_t i = 0; i < desc.point_count; ++i) {
            h.element_first.push_back(i);
            h.weights.push_back(desc.weights != nullptr ? desc.weights[i] : 1.0);
        }
        h.element_first.push_back(desc.point_count);
        return;
    }
    const std::size_t n = desc.samples_per_edge;
    for (std::size_t t = 0; t < desc.triangle_count; ++t) {
        const Vec3 a = point_of(desc.points_xyz_m, desc.triangles[3 * t]);
        const Vec3 b = point_of(desc.points_xyz_m, desc.triangles[3 * t + 1]);
        const Vec3 c = point_of(desc.points_xyz_m, desc.triangles[3 * t + 2]);
        const double area = 0.5 * (b - a).cross(c - a).norm();
        const double weight = area * (desc.weights != nullptr ? desc.weights[t] : 1.0) / double(n * n);
        h.element_first.push_back(h.weights.size());
        // Barycentric (i, j) grid: n (n + 1) / 2 upward sub-triangles, n (n - 1) / 2 downward.
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; i + j < n; ++j) {
                for (double offset : {1.0 / 3.0, 2.0 / 3.0}) {
                    if (offset > 0.5 && i + j + 2 > n) continue;  // no downward triangle on the edge
                    const double u = (double(i) + offset) / double(n), v = (double(j) + offset) / double(n);
                    append(h.local_samples, a + u * (b - a) + v * (c - a));
                    h.weights.push_back(weight);
                }
            }
    }
    h.element_first.push_back(h.weights.size());
}

// Counts before arrays: a count claim far beyond the arrays is refused before they are read.
void check_desc(const ent_exposure_desc& desc) {
    require(desc.points_xyz_m, "desc.points_xyz_m");
    Checked<uint32_t>(desc.point_count, "desc.point_count", ErrorCode::invalid_argument).at_least(1).at_most(kMostPoints);
    if (desc.triangles == nullptr && desc.triangle_count > 0)
        throw Error(ErrorCode::invalid_argument,
                    "desc.triangles is NULL with a triangle_count of " + std::to_string(desc.triangle_count));
    if (desc.triangles != nullptr)
        Checked<uint32_t>(desc.triangle_count, "desc.triangle_count", ErrorCode::invalid_argument)
            .at_least(1)
            .at_most(kMostTriangles);
    Checked<uint32_t>(desc.samples_per_edge, "desc.samples_per_edge", ErrorCode::invalid_argument).at_least(1).at_most(32);
    const uint64_t samples = desc.triangles != nullptr
                                 ? uint64_t{desc.triangle_count} * desc.samples_per_edge * desc.samples_per_edge
                                 : desc.point_count;
    if (samples > kMostSamples)
        throw Error(ErrorCode::invalid_argument, "desc: triangle_count x samples_per_edge^2 is " + std::to_string(samples) +
                                                     " samples, more than " + std::to_string(kMostSamples));
    Checked<uint32_t>(desc.axis_chords_per_segment, "desc.axis_chords_per_segment", ErrorCode::invalid_argument)
        .at_least(1)
        .at_most(64);
    for (std::size_t i = 0; i < 3 * std::size_t{desc.point_count}; ++i)
        if (!std::isfinite(desc.points_xyz_m[i]))
            throw Error(ErrorCode::invalid_argument,
                        "desc.points_xyz_m[" + std::to_string(i / 3) + "] must be finite");
    if (desc.triangles != nullptr)
        for (std::size_t k = 0; k < 3 * std::size_t{desc.triangle_count}; ++k)
            if (desc.triangles[k] >= desc.point_count)
                throw Error(ErrorCode::invalid_argument, "desc.triangles[" + std::to_string(k / 3) + "] has index " +
                                                             std::to_string(desc.triangles[k]) + ", past the " +
                                                             std::to_string(desc.point_count) + " points");
    if (desc.weights != nullptr) {
        const std::size_t count = desc.triangles != nullptr ? desc.triangle_count : desc.point_count;
        for (std::size_t i = 0; i < count; ++i)
            Checked<double>(desc.weights[i], "desc.weights[" + std::to_string(i) + "]", ErrorCode::invalid_argument)
                .at_least(0.0);
    }
}

// The target's frame where the snapshot has it, or NOT_FOUND.
enteron::mechanics::FramePlacement target_frame(const enteron::scene::Snapshot& snapshot, int32_t obstacle) {
    if (obstacle == ENT_NO_OBSTACLE) return {};
    if (obstacle < 0 || static_cast<std::size_t>(obstacle) >= snapshot.obstacles.size() ||
        !snapshot.obstacles[static_cast<std::size_t>(obstacle)].present)
        throw Error(ErrorCode::not_found, "obstacle " + std::to_string(obstacle) +
                                              " (the target's frame) does not exist (or was removed)");
    return enteron::mechanics::placement_at(snapshot.obstacles[static_cast<std::size_t>(obstacle)].pose);
}

// Samples the bowel's axis at chords_per_segment chords per spline segment, evenly in the
// spline's parameter, into the occlusion's tube 0.
void sample_axis(const double* control_points, ExposureHandle& h) {
    double* out = h.occlusion.positions(0);
    const std::size_t samples = h.occlusion.samples(0);
    const double last = double(h.control_points - 1);
    for (std::size_t i = 0; i < samples; ++i) {
        const double s = i + 1 == samples ? last : double(i) / double(h.chords_per_segment);
        const Vec3 p = enteron::spline::evaluate(
            control_points,
            enteron::spline::weights_at(h.control_points, s, enteron::spline::Derivative::value, h.ends));
        out[3 * i] = p.x();
        out[3 * i + 1] = p.y();
        out[3 * i + 2] = p.z();
    }
}

}  // namespace

extern "C" {

ENT_API ent_status ent_exposure_desc_init(ent_exposure_desc* desc, uint32_t struct_size) {
    return guarded([&] {
        require(desc, "desc");
        enteron::capi::check_struct_size(struct_size, {sizeof(ent_exposure_desc)}, "ent_exposure_desc");
        ent_exposure_desc defaults = default_exposure_desc();
        defaults.struct_size = struct_size;
        std::memcpy(desc, &defaults, struct_size);
    });
}

ENT_API ent_status ent_exposure_create(const ent_scene* scene, const ent_exposure_desc* desc,
                                       ent_exposure** out_exposure) {
    return guarded([&] {
        const enteron::capi::SceneCall call(scene);
        const SceneHandle& scene_handle = call.handle();
        require(desc, "desc");
        require(out_exposure, "out_exposure");
        enteron::capi::check_struct_size(desc->struct_size, {sizeof(ent_exposure_desc)}, "ent_exposure_desc");
        check_desc(*desc);
        auto h = std::make_unique<ExposureHandle>();
        h->scene = scene_handle.scene ? &*scene_handle.scene : nullptr;
        h->control_points = scene_handle.published->control_points();
        h->ends = scene_handle.published->ends();
        h->chords_per_segment = desc->axis_chords_per_segment;
        h->obstacle = desc->obstacle;
        {
            const enteron::scene::SnapshotPublisher::Reader snapshot(*scene_handle.published);
            (void)target_frame(*snapshot, desc->obstacle);  // refuses an obstacle that is not there
        }
        sample_target(*desc, *h);
        double total = 0.0;
        for (double w : h->weights) total += w;
        if (!(total > 0.0))
            throw Error(ErrorCode::invalid_argument, desc->triangles != nullptr
                                                         ? "desc: the patch has no weight (every triangle of zero area or weight)"
                                                         : "desc.weights are all zero");
        h->world_samples.resize(h->local_samples.size());
        // Tube 0: the scene's intestine, each sample with the radius at its rest arc length
        // (constant without a radius profile; several tubes are several add_tube calls).
        const std::size_t samples = (h->control_points - 1) * h->chords_per_segment + 1;
        const enteron::scene::Scene& tube = *scene_handle.scene;
        const double sample_length = tube.rest_length() / double(samples - 1);
        std::vector<double> radii(samples);
        for (std::size_t k = 0; k < samples; ++k) radii[k] = tube.radius_at(sample_length * double(k));
        // Runs of two spline segments (5 cm of the 6 m bowel at N = 240): measured fastest
        // among 1, 2 and 4 segments (bench/exposure_bench.cpp).
        h->occlusion.add_tube(0, radii.data(), samples, 2 * h->chords_per_segment);
        h->occlusion.reserve_sight_lines(h->weights.size());
        *out_exposure = reinterpret_cast<ent_exposure*>(h.release());
    });
}

ENT_API void ent_exposure_destroy(ent_exposure* exposure) {
    delete reinterpret_cast<ExposureHandle*>(exposure);
}

ENT_API ent_status ent_scene_exposure(const ent_scene* scene, ent_exposure* exposure, const double viewpoint_m[3],
                                      ent_exposure_result* out) {
    return guarded([&] {
        const enteron::capi::SceneCall call(scene);
        const SceneHandle& scene_handle = call.handle();
        ExposureHandle& h = handle_of(exposure);
        require(viewpoint_m, "viewpoint_m");
        require(out, "out");
        for (int c = 0; c < 3; ++c)
            Checked<double>(viewpoint_m[c], "viewpoint_m[" + std::to_string(c) + "]", ErrorCode::invalid_argument);
        enteron::capi::check_struct_size(out->struct_size, {sizeof(ent_exposure_result)}, "ent_exposure_result");
        if (out->spans_u == nullptr && out->span_capacity > 0)
            throw Error(ErrorCode::invalid_argument,
                        "out.spans_u is NULL with a span_capacity of " + std::to_string(out->span_capacity));
        if (h.scene != &*scene_handle.scene || h.control_points != scene_handle.published->control_points())
            throw Error(ErrorCode::invalid_argument, "exposure was made for another scene (ent_exposure_create)");
        // One query at a time per exposure: its buffers are the query's work space.
        const enteron::capi::ExclusiveCall measuring(h.measuring, [] {
            return std::string("ent_scene_exposure: this exposure is measuring on another thread "
                               "(use one exposure per thread)");
        });
        double time_s = 0.0;
        uint64_t steps = 0;
        {
            // Pin the snapshot only while the axis and the target's frame are read.
            const enteron::scene::SnapshotPublisher::Reader snapshot(*scene_handle.published);
            const enteron::mechanics::FramePlacement frame = target_frame(*snapshot, h.obstacle);
            for (std::size_t i = 0; i < h.weights.size(); ++i)
                enteron::point_at(h.world_samples.data(), i) = frame.to_world(point_of(h.local_samples.data(), i));
            sample_axis(snapshot->control_points.data(), h);
            time_s = snapshot->stats.time;
            steps = snapshot->stats.steps;
        }
        h.occlusion.prepare();
        const Vec3 eye(viewpoint_m[0], viewpoint_m[1], viewpoint_m[2]);
        const enteron::collision::OcclusionTotals totals =
            h.occlusion.measure(eye, h.world_samples.data(), h.weights.data(), h.weights.size());

        const auto& spans = h.occlusion.spans();
        const uint32_t written = std::min(out->span_capacity, static_cast<uint32_t>(spans.size()));
        for (uint32_t k = 0; k < written; ++k) {
            out->spans_u[2 * k] = spans[k].u_first;
            out->spans_u[2 * k + 1] = spans[k].u_last;
            if (out->span_hidden_fractions != nullptr)
                out->span_hidden_fractions[k] = spans[k].hidden_weight / totals.total_weight;
            if (out->span_intestines != nullptr) out->span_intestines[k] = spans[k].tube;
        }
        if (out->element_visible != nullptr)
            for (std::size_t e = 0; e < h.elements; ++e) {
                std::size_t seen = 0;
                for (std::size_t i = h.element_first[e]; i < h.element_first[e + 1]; ++i) seen += h.occlusion.hidden(i) ? 0 : 1;
                out->element_visible[e] = double(seen) / double(h.element_first[e + 1] - h.element_first[e]);
            }
        out->visible_fraction = totals.visible_weight / totals.total_weight;
        out->span_count = static_cast<uint32_t>(spans.size());
        out->samples = static_cast<uint32_t>(h.weights.size());
        out->hidden_samples = static_cast<uint32_t>(totals.hidden_lines);
        out->time_s = time_s;
        out->steps = steps;
    });
}

}  // extern "C"
