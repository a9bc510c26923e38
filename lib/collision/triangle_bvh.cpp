// SPDX-License-Identifier: Apache-2.0
#include "collision/triangle_bvh.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "base/error.h"

namespace enteron::collision {

struct TriangleBvh::Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~Embree() {
        if (scene != nullptr) rtcReleaseScene(scene);
        if (device != nullptr) rtcReleaseDevice(device);
    }
};

namespace {

[[noreturn]] void fail(RTCDevice device, const char* what) {
    const RTCError error = device != nullptr ? rtcGetDeviceError(device) : RTC_ERROR_UNKNOWN;
    if (error == RTC_ERROR_OUT_OF_MEMORY) throw Error(ErrorCode::out_of_memory, std::string(what) + ": out of memory");
    throw Error(ErrorCode::internal, std::string(what) + " failed (Embree error " + std::to_string(int(error)) + ")");
}

struct Search {
    const TriangleMesh* mesh;
    const MeshTopology* topology;
    Vec3 p;
    TriangleBvh::Closest best;
};

// Called by Embree for each triangle whose box meets the query sphere; shrinks the sphere to
// the best distance so far.
bool visit(RTCPointQueryFunctionArguments* args) {
    Search& search = *static_cast<Search*>(args->userPtr);
    const uint32_t t = args->primID;
    if (!search.topology->usable(t)) return false;
    const TriangleMesh& m = *search.mesh;
    const TrianglePoint q = closest_point_on_triangle(search.p, m.corner(t, 0), m.corner(t, 1), m.corner(t, 2));
    const double distance = (q.point - search.p).norm();
    if (!(distance < search.best.distance)) return false;
    search.best = {t, q, distance};
    // Embree works in single precision: keep its sphere a hair larger than ours.
    args->query->radius = static_cast<float>(distance) * (1.0f + 1e-6f) + 1e-9f;
    return true;
}

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh, const MeshTopology& topology)
    : embree_(std::make_unique<Embree>()), mesh_(mesh), topology_(topology) {
    // One thread: a library must not start threads its caller did not ask for.
    embree_->device = rtcNewDevice("threads=1,verbose=0");
    if (embree_->device == nullptr) fail(nullptr, "Embree device");
    embree_->scene = rtcNewScene(embree_->device);
    if (embree_->scene == nullptr) fail(embree_->device, "Embree scene");
    RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (geometry == nullptr) fail(embree_->device, "Embree geometry");
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.vertex_count()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(uint32_t), mesh.triangle_count()));
    if (vertices == nullptr || indices == nullptr) {
        rtcReleaseGeometry(geometry);
        fail(embree_->device, "Embree buffers");
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) vertices[i] = static_cast<float>(mesh.vertices[i]);
    // Unusable (zero-area) triangles repeat a corner: Embree skips them, and visit() never
    // sees one. The primitive ids stay the mesh's triangle numbers.
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
        for (int k = 0; k < 3; ++k) indices[3 * t + k] = mesh.indices[3 * t + (topology.usable(t) ? k : 0)];
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(embree_->scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(embree_->scene);
    if (rtcGetDeviceError(embree_->device) != RTC_ERROR_NONE) fail(embree_->device, "Embree hierarchy");
}

TriangleBvh::~TriangleBvh() = default;

TriangleBvh::Closest TriangleBvh::closest(const Vec3& p, double bound) const {
    Search search{&mesh_, &topology_, p, {}};
    search.best.distance = std::numeric_limits<double>::infinity();
    RTCPointQuery query;
    query.x = static_cast<float>(p.x());
    query.y = static_cast<float>(p.y());
    query.z = static_cast<float>(p.z());
    query.time = 0.0f;
    const float largest = std::numeric_limits<float>::max();
    query.radius = std::isfinite(bound) ? static_cast<float>(bound) * (1.0f + 1e-5f) + 1e-7f : largest;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(embree_->scene, &query, &context, visit, &search);
    if (!std::isfinite(search.best.distance) && query.radius < largest) {
        // The bound was too tight after rounding: search everywhere.
        query.radius = largest;
        rtcPointQuery(embree_->scene, &query, &context, visit, &search);
    }
    return search.best;
}

}  // namespace enteron::collision
