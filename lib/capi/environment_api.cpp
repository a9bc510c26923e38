// SPDX-License-Identifier: Apache-2.0
// The environment entry points of the C API: rigid obstacles around the bowel, which the
// caller may move, re-grip and remove between steps.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <memory>
#include <optional>
#include <string>

#include "capi/call_guard.h"
#include "capi/driving_call.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "scene/plausible_ranges.h"
#include "scene/scene_config.h"
#include "scene/validate.h"

namespace {

using enteron::Error;
using enteron::ErrorCode;
using enteron::capi::SceneHandle;
using enteron::capi::guarded;
using enteron::capi::SceneCall;
using enteron::capi::require;

enteron::Vec3 vec3(const double v[3]) { return {v[0], v[1], v[2]}; }

// The sizes of ent_obstacle_desc in released headers: before moving anatomy, and now.
constexpr std::size_t kObstacleDescBeforeMeshes = offsetof(ent_obstacle_desc, mesh_vertices_xyz_m);

// The obstacle in the library's terms: centre/point/start, extent (half extents, normal or
// end), radius, and for a mesh a copy of the caller's arrays (checked for NULL here, for
// their values by the validation).
enteron::collision::Obstacle obstacle_from(const ent_obstacle_desc& desc) {
    using enteron::collision::ObstacleKind;
    enteron::collision::Obstacle obstacle;
    obstacle.kind = static_cast<ObstacleKind>(desc.kind);
    obstacle.radius = desc.radius_m;
    switch (obstacle.kind) {
        case ObstacleKind::box_inside:
            obstacle.center = vec3(desc.center_m);
            obstacle.extent = vec3(desc.half_extents_m);
            break;
        case ObstacleKind::plane:
            obstacle.center = vec3(desc.center_m);
            obstacle.extent = vec3(desc.normal);
            break;
        case ObstacleKind::sphere: obstacle.center = vec3(desc.center_m); break;
        case ObstacleKind::capsule:
            obstacle.center = vec3(desc.start_m);
            obstacle.extent = vec3(desc.end_m);
            break;
        case ObstacleKind::mesh: {
            // Counts first: a claim beyond the limit is refused before its arrays are read.
            if (desc.mesh_triangle_count > enteron::collision::kMaxMeshTriangles)
                throw Error(ErrorCode::invalid_argument,
                            "mesh_triangle_count is " + std::to_string(desc.mesh_triangle_count) +
                                ", more than the " + std::to_string(enteron::collision::kMaxMeshTriangles) +
                                " a mesh obstacle may have");
            if (desc.mesh_vertex_count > 3 * enteron::collision::kMaxMeshTriangles)
                throw Error(ErrorCode::invalid_argument,
                            "mesh_vertex_count is " + std::to_string(desc.mesh_vertex_count) + ", more than 3 x " +
                                std::to_string(enteron::collision::kMaxMeshTriangles));
            if (desc.mesh_vertex_count > 0) require(desc.mesh_vertices_xyz_m, "mesh_vertices_xyz_m");
            if (desc.mesh_triangle_count > 0) require(desc.mesh_triangles, "mesh_triangles");
            auto mesh = std::make_shared<enteron::collision::TriangleMesh>();
            mesh->vertices.assign(desc.mesh_vertices_xyz_m, desc.mesh_vertices_xyz_m + 3 * std::size_t{desc.mesh_vertex_count});
            mesh->indices.assign(desc.mesh_triangles, desc.mesh_triangles + 3 * std::size_t{desc.mesh_triangle_count});
            obstacle.mesh = std::move(mesh);
            obstacle.voxel_size = desc.mesh_voxel_size_m;
            break;
        }
    }
    obstacle.pose.position = vec3(desc.position_m);
    obstacle.pose.orientation.coeffs() << desc.orientation_wxyz[1], desc.orientation_wxyz[2], desc.orientation_wxyz[3],
        desc.orientation_wxyz[0];
    obstacle.friction = desc.friction;
    return obstacle;
}

// The defaults of every field, as ent_obstacle_desc_default gives them.
ent_obstacle_desc default_obstacle_desc() {
    ent_obstacle_desc defaults;
    std::memset(&defaults, 0, sizeof defaults);
    defaults.struct_size = sizeof defaults;
    using enteron::collision::ObstacleKind;
    using enteron::scene::default_obstacle;
    const enteron::collision::Obstacle box = default_obstacle(ObstacleKind::box_inside);
    const enteron::collision::Obstacle plane = default_obstacle(ObstacleKind::plane);
    const enteron::collision::Obstacle capsule = default_obstacle(ObstacleKind::capsule);
    defaults.kind = static_cast<int32_t>(box.kind);
    for (int c = 0; c < 3; ++c) {
        defaults.center_m[c] = box.center[c];
        defaults.half_extents_m[c] = box.extent[c];
        defaults.normal[c] = plane.extent[c];
        defaults.start_m[c] = capsule.center[c];
        defaults.end_m[c] = capsule.extent[c];
        defaults.position_m[c] = box.pose.position[c];
    }
    defaults.radius_m = capsule.radius;
    defaults.orientation_wxyz[0] = box.pose.orientation.w();
    defaults.orientation_wxyz[1] = box.pose.orientation.x();
    defaults.orientation_wxyz[2] = box.pose.orientation.y();
    defaults.orientation_wxyz[3] = box.pose.orientation.z();
    defaults.friction = box.friction;
    return defaults;
}

// An obstacle id of this scene (present or removed), or NOT_FOUND naming it. The driving
// thread.
std::size_t obstacle_index(const enteron::scene::Scene& scene, int32_t obstacle) {
    if (obstacle < 0 || static_cast<std::size_t>(obstacle) >= scene.obstacle_indices())
        throw Error(ErrorCode::not_found, "obstacle " + std::to_string(obstacle) + " does not exist (the scene has had " +
                                              std::to_string(scene.obstacle_indices()) + " obstacles)");
    return static_cast<std::size_t>(obstacle);
}

void require_control_point(const enteron::scene::Scene& scene, uint32_t control_point) {
    if (control_point >= scene.control_points())
        throw Error(ErrorCode::invalid_argument, "control_point must be < " + std::to_string(scene.control_points()) +
                                                     ", got " + std::to_string(control_point));
}

void require_finite(const double* values, int count, const char* name) {
    require(values, name);
    for (int c = 0; c < count; ++c)
        if (!std::isfinite(values[c]))
            throw Error(ErrorCode::invalid_argument,
                        std::string(name) + "[" + std::to_string(c) + "] must be finite, got " + std::to_string(values[c]));
}

// A published obstacle, or NOT_FOUND. Any thread.
enteron::scene::ObstacleOutput published_obstacle(const SceneHandle& handle, int32_t obstacle) {
    const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
    if (obstacle < 0 || static_cast<std::size_t>(obstacle) >= snapshot->obstacles.size() ||
        !snapshot->obstacles[static_cast<std::size_t>(obstacle)].present)
        throw Error(ErrorCode::not_found, "obstacle " + std::to_string(obstacle) + " does not exist (or was removed)");
    return snapshot->obstacles[static_cast<std::size_t>(obstacle)];
}

}  // namespace

extern "C" {

ENT_API ent_status ent_obstacle_desc_init(ent_obstacle_desc* desc, uint32_t struct_size) {
    return guarded([&] {
        require(desc, "desc");
        enteron::capi::check_struct_size(struct_size, {kObstacleDescBeforeMeshes, sizeof(ent_obstacle_desc)},
                                         "ent_obstacle_desc");
        ent_obstacle_desc defaults = default_obstacle_desc();
        defaults.struct_size = struct_size;
        std::memcpy(desc, &defaults, struct_size);
    });
}

ENT_API ent_status ent_scene_add_obstacle(ent_scene* scene, const ent_obstacle_desc* desc, int32_t* out_obstacle) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        require(desc, "desc");
        enteron::capi::check_struct_size(desc->struct_size, {kObstacleDescBeforeMeshes, sizeof(ent_obstacle_desc)},
                                         "ent_obstacle_desc");
        // An older caller's struct ends at its size: the fields it lacks get their defaults.
        ent_obstacle_desc complete = default_obstacle_desc();
        std::memcpy(&complete, desc, desc->struct_size);
        const enteron::capi::DrivingCall driving(handle, "ent_scene_add_obstacle");
        enteron::scene::Scene& s = *handle.scene;
        const std::string name = "obstacle[" + std::to_string(s.obstacle_indices()) + "]";
        // An unknown kind picks no field and is refused by the validation.
        const enteron::scene::FieldNames& names = enteron::scene::c_field_names();
        const enteron::collision::Obstacle obstacle =
            enteron::scene::validate_obstacle(obstacle_from(complete), name, names);
        enteron::scene::warn_implausible(obstacle, name, handle.logger);
        // The scene checks the bowel's start against it (a mesh once its field is built).
        const std::size_t index = s.add_obstacle(obstacle, name, names);
        if (out_obstacle != nullptr) *out_obstacle = static_cast<int32_t>(index);
    });
}

ENT_API ent_status ent_obstacle_set_pose(ent_scene* scene, int32_t obstacle, const double position_m[3],
                                         const double orientation_wxyz[4]) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        require_finite(position_m, 3, "position_m");
        require_finite(orientation_wxyz, 4, "orientation_wxyz");
        const std::array<double, 4> q = enteron::scene::unit_quaternion(
            {orientation_wxyz[0], orientation_wxyz[1], orientation_wxyz[2], orientation_wxyz[3]},
            [] { return std::string("orientation_wxyz"); }, ErrorCode::invalid_argument);
        const enteron::capi::DrivingCall driving(handle, "ent_obstacle_set_pose");
        enteron::mechanics::RigidPose pose;
        pose.position = vec3(position_m);
        pose.orientation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
        handle.scene->set_obstacle_pose(obstacle_index(*handle.scene, obstacle), pose);
    });
}

ENT_API ent_status ent_obstacle_set_velocity(ent_scene* scene, int32_t obstacle, const double linear_m_per_s[3],
                                             const double angular_rad_per_s[3]) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        require_finite(linear_m_per_s, 3, "linear_m_per_s");
        require_finite(angular_rad_per_s, 3, "angular_rad_per_s");
        const enteron::capi::DrivingCall driving(handle, "ent_obstacle_set_velocity");
        handle.scene->set_obstacle_velocity(obstacle_index(*handle.scene, obstacle), vec3(linear_m_per_s),
                                            vec3(angular_rad_per_s));
    });
}

ENT_API ent_status ent_obstacle_set_friction(ent_scene* scene, int32_t obstacle, double friction) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        if (std::isnan(friction) || std::isinf(friction))
            throw Error(ErrorCode::invalid_argument, "friction must be finite (>= 0, or negative for the scene's)");
        const enteron::capi::DrivingCall driving(handle, "ent_obstacle_set_friction");
        handle.scene->set_obstacle_friction(obstacle_index(*handle.scene, obstacle), friction);
    });
}

ENT_API ent_status ent_scene_remove_obstacle(ent_scene* scene, int32_t obstacle) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        const enteron::capi::DrivingCall driving(handle, "ent_scene_remove_obstacle");
        handle.scene->remove_obstacle(obstacle_index(*handle.scene, obstacle));
    });
}

ENT_API ent_status ent_scene_obstacle_count(const ent_scene* scene, uint32_t* out_count) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out_count, "out_count");
        const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
        uint32_t count = 0;
        for (const enteron::scene::ObstacleOutput& o : snapshot->obstacles) count += o.present ? 1 : 0;
        *out_count = count;
    });
}

ENT_API ent_status ent_obstacle_pose(const ent_scene* scene, int32_t obstacle, double position_m[3],
                                     double orientation_wxyz[4]) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(position_m, "position_m");
        require(orientation_wxyz, "orientation_wxyz");
        const enteron::mechanics::RigidPose pose = published_obstacle(handle, obstacle).pose;
        for (int c = 0; c < 3; ++c) position_m[c] = pose.position[c];
        orientation_wxyz[0] = pose.orientation.w();
        orientation_wxyz[1] = pose.orientation.x();
        orientation_wxyz[2] = pose.orientation.y();
        orientation_wxyz[3] = pose.orientation.z();
    });
}

ENT_API ent_status ent_obstacle_mesh(ent_scene* scene, int32_t obstacle, uint32_t vertex_capacity,
                                     double* vertices_xyz_m, uint32_t* out_vertex_count, uint32_t triangle_capacity,
                                     uint32_t* triangles, uint32_t* out_triangle_count) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        require(out_vertex_count, "out_vertex_count");
        require(out_triangle_count, "out_triangle_count");
        const enteron::capi::DrivingCall driving(handle, "ent_obstacle_mesh");
        const enteron::collision::Obstacle& o = handle.scene->obstacle(obstacle_index(*handle.scene, obstacle));
        if (o.kind != enteron::collision::ObstacleKind::mesh)
            throw Error(ErrorCode::invalid_argument, "obstacle " + std::to_string(obstacle) + " is not a mesh");
        const enteron::collision::TriangleMesh& mesh = o.field->mesh();
        *out_vertex_count = static_cast<uint32_t>(mesh.vertex_count());
        *out_triangle_count = static_cast<uint32_t>(mesh.triangle_count());
        if ((vertices_xyz_m != nullptr && vertex_capacity < mesh.vertex_count()) ||
            (triangles != nullptr && triangle_capacity < mesh.triangle_count()))
            throw Error(ErrorCode::buffer_too_small,
                        "the mesh has " + std::to_string(mesh.vertex_count()) + " vertices and " +
                            std::to_string(mesh.triangle_count()) + " triangles; the capacities are " +
                            std::to_string(vertex_capacity) + " and " + std::to_string(triangle_capacity));
        if (vertices_xyz_m != nullptr) std::copy(mesh.vertices.begin(), mesh.vertices.end(), vertices_xyz_m);
        if (triangles != nullptr) std::copy(mesh.indices.begin(), mesh.indices.end(), triangles);
    });
}

ENT_API ent_status ent_scene_set_gravity(ent_scene* scene, const double gravity_m_per_s2[3]) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        require_finite(gravity_m_per_s2, 3, "gravity_m_per_s2");
        const enteron::capi::DrivingCall driving(handle, "ent_scene_set_gravity");
        handle.scene->set_gravity(vec3(gravity_m_per_s2));
    });
}

ENT_API ent_status ent_scene_pin_point(ent_scene* scene, uint32_t control_point, int32_t obstacle) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        const enteron::capi::DrivingCall driving(handle, "ent_scene_pin_point");
        enteron::scene::Scene& s = *handle.scene;
        require_control_point(s, control_point);
        std::optional<std::size_t> frame;
        if (obstacle != ENT_NO_OBSTACLE) frame = obstacle_index(s, obstacle);
        s.pin_point(control_point, frame);
    });
}

ENT_API ent_status ent_scene_unpin_point(ent_scene* scene, uint32_t control_point) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        const enteron::capi::DrivingCall driving(handle, "ent_scene_unpin_point");
        enteron::scene::Scene& s = *handle.scene;
        require_control_point(s, control_point);
        if (!s.unpin_point(control_point))
            throw Error(ErrorCode::not_found, "control point " + std::to_string(control_point) + " is not pinned");
    });
}

ENT_API ent_status ent_scene_attach_mesentery(ent_scene* scene, int32_t obstacle) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        const enteron::capi::DrivingCall driving(handle, "ent_scene_attach_mesentery");
        enteron::scene::Scene& s = *handle.scene;
        std::optional<std::size_t> frame;
        if (obstacle != ENT_NO_OBSTACLE) frame = obstacle_index(s, obstacle);
        s.attach_mesentery(frame);
    });
}

ENT_API ent_status ent_scene_attach_clamped_end(ent_scene* scene, int32_t ends, int32_t obstacle) {
    return guarded([&] {
        const SceneCall call(scene);
        SceneHandle& handle = call.handle();
        if (ends != ENT_PIN_FIRST && ends != ENT_PIN_LAST && ends != ENT_PIN_BOTH)
            throw Error(ErrorCode::invalid_argument, "ent_scene_attach_clamped_end: ends is " + std::to_string(ends) +
                                                         ", not ENT_PIN_FIRST (1), ENT_PIN_LAST (2) or ENT_PIN_BOTH (3)");
        const enteron::capi::DrivingCall driving(handle, "ent_scene_attach_clamped_end");
        enteron::scene::Scene& s = *handle.scene;
        std::optional<std::size_t> frame;
        if (obstacle != ENT_NO_OBSTACLE) frame = obstacle_index(s, obstacle);
        s.attach_clamped_ends(ends, frame);
    });
}

}  // extern "C"
