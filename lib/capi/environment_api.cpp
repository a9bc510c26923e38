// The environment entry points of the C API: rigid obstacles around the bowel.
#include <cstring>
#include <string>

#include "capi/call_guard.h"
#include "capi/driving_call.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "scene/plausible_ranges.h"
#include "scene/scene_config.h"
#include "scene/validate.h"

namespace {

enteron::Vec3 vec3(const double v[3]) { return {v[0], v[1], v[2]}; }

// The obstacle in the library's terms: centre/point/start, extent (half extents, normal or
// end) and radius.
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
    }
    return obstacle;
}

}  // namespace

extern "C" {

ENT_API ent_status ent_obstacle_desc_init(ent_obstacle_desc* desc, uint32_t struct_size) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(desc, "desc");
        enteron::capi::check_struct_size(struct_size, {sizeof(ent_obstacle_desc)}, "ent_obstacle_desc");
        ent_obstacle_desc defaults;
        std::memset(&defaults, 0, sizeof defaults);
        defaults.struct_size = struct_size;
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
        }
        defaults.radius_m = capsule.radius;
        std::memcpy(desc, &defaults, struct_size);
    });
}

ENT_API ent_status ent_scene_add_obstacle(ent_scene* scene, const ent_obstacle_desc* desc, int32_t* out_obstacle) {
    return enteron::capi::guarded([&] {
        enteron::capi::SceneHandle& handle = enteron::capi::live_handle(scene);
        enteron::capi::require(desc, "desc");
        enteron::capi::check_struct_size(desc->struct_size, {sizeof(ent_obstacle_desc)}, "ent_obstacle_desc");
        const enteron::capi::DrivingCall driving(handle, "ent_scene_add_obstacle");
        enteron::scene::Scene& s = *handle.scene;
        const enteron::collision::Obstacle obstacle = obstacle_from(*desc);
        // Validated before the kind is used to pick fields (an unknown kind is refused here),
        // and against where the bowel is now.
        const std::string name = "obstacle[" + std::to_string(s.obstacle_count()) + "]";
        enteron::scene::validate_obstacle(obstacle, name, enteron::scene::c_field_names(), s.positions().data(),
                                          s.control_points(), &s.start_clearance());
        enteron::scene::warn_implausible(obstacle, name, handle.logger);
        const std::size_t index = s.add_obstacle(obstacle);
        if (out_obstacle != nullptr) *out_obstacle = static_cast<int32_t>(index);
    });
}

}  // extern "C"
