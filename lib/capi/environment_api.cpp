// The environment entry points of the C API: rigid obstacles around the bowel.
#include <cstring>

#include "capi/call_guard.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "scene/validate.h"

static_assert(ENT_OBSTACLE_CAPSULE == static_cast<int>(enteron::collision::ObstacleKind::capsule));
static_assert(ENT_EFFECT_ENVIRONMENT == static_cast<int>(enteron::EffectId::environment));
static_assert(ENT_EFFECT_SELF_COLLISION == static_cast<int>(enteron::EffectId::self_collision));

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
        defaults.kind = ENT_OBSTACLE_BOX_INSIDE;
        for (int c = 0; c < 3; ++c) defaults.half_extents_m[c] = 0.12;
        defaults.normal[2] = 1.0;
        defaults.end_m[2] = 0.1;
        defaults.radius_m = 0.05;
        std::memcpy(desc, &defaults, struct_size);
    });
}

ENT_API ent_status ent_scene_add_obstacle(ent_scene* scene, const ent_obstacle_desc* desc, int32_t* out_obstacle) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(scene, "scene");
        enteron::capi::require(desc, "desc");
        enteron::capi::check_struct_size(desc->struct_size, {sizeof(ent_obstacle_desc)}, "ent_obstacle_desc");
        enteron::scene::Scene& s = *enteron::capi::handle_of(scene)->scene;
        const enteron::collision::Obstacle obstacle = obstacle_from(*desc);
        // Validated before the kind is used to pick fields (an unknown kind is refused here).
        enteron::scene::validate_obstacle(obstacle, s.obstacle_count(), enteron::scene::c_field_names());
        const std::size_t index = s.add_obstacle(obstacle);
        if (out_obstacle != nullptr) *out_obstacle = static_cast<int32_t>(index);
    });
}

}  // extern "C"
