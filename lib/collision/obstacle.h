// SPDX-License-Identifier: Apache-2.0
// Rigid shapes around the bowel: the abdominal cavity (inside of a box) and other organs
// (planes, spheres, capsules, triangle meshes). Each reports, for a sphere of radius R, the
// contacts it makes: depth of penetration and the unit normal pushing the sphere out.
//
// Every obstacle has a frame (its pose, mechanics/rigid_frames.h) and its shape is given in
// that frame; the functions here take points in the frame and give normals in it. A frame
// at the identity pose is the world.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "base/geometry.h"
#include "collision/mesh_distance_field.h"
#include "collision/triangle_mesh.h"
#include "mechanics/rigid_frames.h"

namespace enteron::collision {

// The numbers are those of ENT_OBSTACLE_* in enteron.h.
enum class ObstacleKind : int32_t { box_inside = 0, plane = 1, sphere = 2, capsule = 3, mesh = 4 };

struct Obstacle {
    ObstacleKind kind = ObstacleKind::box_inside;
    Vec3 center = Vec3::Zero();  // box_inside, sphere: centre; plane: a point of it; capsule: axis start
    Vec3 extent = Vec3::Zero();  // box_inside: half extents; plane: normal (unit); capsule: axis end
    double radius = 0.0;  // sphere, capsule
    // mesh: its triangles (copied once from the caller, then shared) and the edge of its
    // distance field's voxels, m (0: the scene's default, kDefaultVoxelRadii R).
    std::shared_ptr<const TriangleMesh> mesh;
    double voxel_size = 0.0;
    // Where the frame the shape is given in starts (identity: the shape as given, in the world).
    mechanics::RigidPose pose;
    // Coulomb coefficient of this obstacle's contacts; negative: the scene's.
    double friction = -1.0;
    // mesh: the prepared field (EnvironmentForce::prepare), shared by the copies.
    std::shared_ptr<const MeshDistanceField> field;
};

// A mesh's voxel size when the obstacle leaves it to the scene, in units of the bowel's
// radius R (docs/anatomy.md: the measurement behind it).
constexpr double kDefaultVoxelRadii = 0.25;

struct ObstacleContact {
    double depth;  // m, > 0
    Vec3 normal;   // unit, out of the obstacle
};

// The point of a sphere obstacle's centre, or of a capsule's axis segment, closest to p.
inline Vec3 closest_core_point(const Obstacle& o, const Vec3& p) {
    if (o.kind != ObstacleKind::capsule) return o.center;
    const Vec3 axis = o.extent - o.center;
    const double axis2 = axis.squaredNorm();
    const double t = axis2 > 0.0 ? std::min(1.0, std::max(0.0, axis.dot(p - o.center) / axis2)) : 0.0;
    return o.center + t * axis;
}

// How far the point p (in the obstacle's frame) lies beyond the obstacle's surface, m (<= 0:
// on the bowel's side): outside the box_inside, behind the plane (its normal need not be
// unit), inside the sphere, capsule or mesh (whose field must be prepared).
inline double beyond_surface(const Obstacle& o, const Vec3& p) {
    switch (o.kind) {
        case ObstacleKind::box_inside: return ((p - o.center).cwiseAbs() - o.extent).maxCoeff();
        case ObstacleKind::plane: return -(p - o.center).dot(o.extent) / o.extent.norm();
        case ObstacleKind::sphere:
        case ObstacleKind::capsule: return o.radius - (p - closest_core_point(o, p)).norm();
        case ObstacleKind::mesh: return -o.field->distance(p);
    }
    return 0.0;
}

// Calls on_contact(const ObstacleContact&) for each contact of a sphere (centre p,
// radius r) with the obstacle: up to three for a box corner, at most one otherwise.
// Always inlined: the environment calls it for every sphere and obstacle, and the call
// cost more than a box's six wall tests.
template <class OnContact>
[[gnu::always_inline]] inline void for_each_contact(const Obstacle& o, const Vec3& p, double r, OnContact&& on_contact) {
    switch (o.kind) {
        case ObstacleKind::box_inside: {
            // Each wall is a plane facing inward. Most spheres touch none: one test for all
            // six walls first, without a branch per wall.
            const Vec3 low = (o.center - o.extent) - (p.array() - r).matrix();
            const Vec3 high = (p.array() + r).matrix() - (o.center + o.extent);
            if (!((low.array() > 0.0).any() || (high.array() > 0.0).any())) return;
            for (int c = 0; c < 3; ++c) {
                if (low[c] > 0.0) on_contact(ObstacleContact{low[c], Vec3::Unit(c)});
                if (high[c] > 0.0) on_contact(ObstacleContact{high[c], -Vec3::Unit(c)});
            }
            return;
        }
        case ObstacleKind::plane: {
            const Vec3& n = o.extent;
            const double distance = (p - o.center).dot(n);
            if (distance < r) on_contact(ObstacleContact{r - distance, n});
            return;
        }
        case ObstacleKind::sphere:
        case ObstacleKind::capsule: {
            const Vec3 d = p - closest_core_point(o, p);
            const double distance = d.norm();
            const double depth = o.radius + r - distance;
            if (!(depth > 0.0)) return;
            // A centre exactly on the axis has no direction: push up, any direction will do.
            on_contact(ObstacleContact{depth, distance > 1e-12 ? Vec3(d / distance) : Vec3::UnitZ()});
            return;
        }
        case ObstacleKind::mesh: {
            MeshDistanceField::Sample sample;
            if (o.field->sample_within(p, r, &sample)) on_contact(ObstacleContact{r - sample.distance, sample.normal});
            return;
        }
    }
}

}  // namespace enteron::collision
