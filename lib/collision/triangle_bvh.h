// SPDX-License-Identifier: Apache-2.0
// The closest triangle of a mesh to a point, through Embree's bounding volume hierarchy
// (Debian's libembree-dev; the measurements that chose it are in docs/anatomy.md). Embree
// traverses the hierarchy; the exact point-triangle distance is ours
// (closest_point_on_triangle.h), in double precision.
//
// Used only while a mesh obstacle is prepared (mesh_distance_field.h), never in a step.
// Embree stays behind this file: no Embree type or symbol reaches any other header, and
// libenteron.so exports none (lib/capi/enteron.map).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "collision/closest_point_on_triangle.h"
#include "collision/mesh_topology.h"
#include "collision/triangle_mesh.h"

namespace enteron::collision {

class TriangleBvh {
public:
    // Builds the hierarchy over the usable triangles of `mesh` (which must outlive it).
    // Throws Error(out_of_memory) or Error(internal) with Embree's message.
    TriangleBvh(const TriangleMesh& mesh, const MeshTopology& topology);
    ~TriangleBvh();
    TriangleBvh(const TriangleBvh&) = delete;
    TriangleBvh& operator=(const TriangleBvh&) = delete;

    struct Closest {
        uint32_t triangle = 0;
        TrianglePoint point{Vec3::Zero(), TriangleFeature::face};
        double distance = 0.0;  // m
    };
    // The closest point of the mesh to p. `bound` is a distance (m) known to be at least the
    // answer's (the search starts with it); infinity when nothing is known.
    Closest closest(const Vec3& p, double bound) const;

private:
    struct Embree;
    std::unique_ptr<Embree> embree_;
    const TriangleMesh& mesh_;
    const MeshTopology& topology_;
};

}  // namespace enteron::collision
