// SPDX-License-Identifier: Apache-2.0
// A triangle mesh prepared for contact: its signed distance field on a regular grid in the
// obstacle's frame, built once when the obstacle is added, and read by trilinear
// interpolation in every step (a few loads and no search).
//
// Build: the grid covers the mesh's bounding box widened by `band` on every side. In blocks
// of 4^3 voxels, the distance at the block's centre comes from the closest triangle
// (triangle_bvh.h, Embree); a block that reaches within `band` of the surface gets the exact
// distance at each voxel, the others the first-order extension d(c) + n(c) . (x - c) from
// their centre, which is all a point deep inside or far outside needs (a direction and a
// depth). Signs come from the pseudo-normal of the closest feature (mesh_topology.h): exact
// inside a closed mesh, by the triangles' normals for an open one. Each voxel also keeps its
// closest triangle.
//
// Read: the distance and its gradient by trilinear interpolation of the 8 voxels around the
// point. Where the field is coarse (refine on: voxels larger than the scene asks), a point
// near the surface takes the exact closest point among the closest triangles of those 8
// voxels: exact wherever one of them is the closest triangle, and never worse than the
// field. Outside the grid the distance grows with the distance to the grid.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/mesh_topology.h"
#include "collision/triangle_mesh.h"

namespace enteron::collision {

struct DistanceFieldSettings {
    double voxel_size = 0.0;  // m, > 0
    double band = 0.0;        // m: exact distances within this of the surface; the grid's margin
    bool refine = false;      // exact closest points near the surface (a coarse field)
};

// The most voxels one field may have (8 bytes each: 256 MiB).
constexpr std::size_t kMaxFieldVoxels = std::size_t{1} << 25;

class MeshDistanceField {
public:
    // Prepares `mesh` (checked: finite, indices in range, a usable triangle). Throws
    // Error(invalid_argument) when the grid would need more than kMaxFieldVoxels voxels (the
    // message says which voxel size would fit), Error(out_of_memory), Error(internal).
    MeshDistanceField(const TriangleMesh& mesh, const DistanceFieldSettings& settings, std::pmr::memory_resource* memory);
    MeshDistanceField(const MeshDistanceField&) = delete;  // the topology refers to mesh_
    MeshDistanceField& operator=(const MeshDistanceField&) = delete;

    struct Sample {
        double distance;  // m, > 0 on the bowel's side of the surface
        Vec3 normal;      // unit, out of the obstacle (toward the bowel's side)
    };
    // The distance and normal at a point p of the obstacle's frame; false (out unset) when p
    // is surely more than `reach` (<= band) from the surface on the bowel's side.
    bool sample_within(const Vec3& p, double reach, Sample* out) const;
    // The signed distance at p (m), anywhere.
    double distance(const Vec3& p) const;

    const TriangleMesh& mesh() const { return mesh_; }
    const MeshTopologyReport& report() const { return topology_.report(); }
    const DistanceFieldSettings& settings() const { return settings_; }
    std::size_t voxel_count() const { return distances_.size(); }
    // Bytes held: grid, triangles and normals.
    std::size_t memory_bytes() const;
    // True when the region outside the grid is inside the obstacle (a cavity's wall,
    // normals facing inward).
    bool outside_is_solid() const { return outside_solid_; }

private:
    void build();
    std::size_t index(std::size_t x, std::size_t y, std::size_t z) const { return (z * ny_ + y) * nx_ + x; }
    Vec3 voxel_position(std::size_t x, std::size_t y, std::size_t z) const {
        return low_ + voxel_ * Vec3(double(x), double(y), double(z));
    }
    // Trilinear interpolation at p, clamped to the grid: distance and gradient, and the cell.
    struct Cell {
        std::size_t base;  // index of the low corner
        double distance;
        Vec3 gradient;
    };
    Cell interpolate(const Vec3& p) const;
    // The exact closest point among the closest triangles of the cell's corners.
    Sample refined(const Vec3& p, const Cell& cell) const;
    Sample sample_in_grid(const Vec3& p, const Cell& cell) const;

    TriangleMesh mesh_;
    MeshTopology topology_;
    DistanceFieldSettings settings_;
    double voxel_;
    double inverse_voxel_;
    Vec3 low_;   // the grid's first voxel, m (frame)
    Vec3 high_;  // its last
    std::size_t nx_ = 0, ny_ = 0, nz_ = 0;
    std::pmr::vector<float> distances_;    // m
    std::pmr::vector<int32_t> triangles_;  // closest triangle of each voxel
    bool outside_solid_ = false;
};

}  // namespace enteron::collision
