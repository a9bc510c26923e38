// SPDX-License-Identifier: Apache-2.0
#include "capi/scene_desc.h"

#include <cstddef>
#include <cstring>
#include <utility>

#include "capi/call_guard.h"
#include "capi/struct_size.h"
#include "scene/validate.h"

namespace enteron::capi {

namespace {

// Larger inputs than these are refused before anything is copied from the caller's arrays.
constexpr uint32_t kMaxControlPoints = 100000;

Vec3 vec3(const double v[3]) { return {v[0], v[1], v[2]}; }

// The defaults of the current ent_scene_desc, whole: those of a default SceneConfig (one
// set for JSON and C), with gravity and damping turned on.
ent_scene_desc default_desc() {
    ent_scene_desc desc;
    const scene::SceneConfig defaults;
    const scene::IntestineConfig& intestine = defaults.intestine;
    const scene::ShapeConfig& shape = intestine.shape;
    const scene::DampingConfig damping;
    const scene::MesenteryConfig mesentery;
    std::memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc;
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
    desc.length_m = intestine.length;
    desc.radius_m = intestine.radius;
    desc.control_points = static_cast<uint32_t>(intestine.control_points);
    desc.linear_density_kg_per_m = intestine.linear_density;
    desc.stretch_stiffness_N = intestine.stretch_stiffness;
    desc.bend_stiffness_N_m2 = intestine.bend_stiffness;
    desc.shape = static_cast<int32_t>(shape.kind);
    for (int c = 0; c < 3; ++c) {
        desc.shape_center_m[c] = shape.center[c];
        desc.shape_direction[c] = shape.direction[c];
        desc.gravity_m_per_s2[c] = scene::kStandardGravity[c];
        desc.mesentery_root_start_m[c] = mesentery.root_start[c];
        desc.mesentery_root_end_m[c] = mesentery.root_end[c];
    }
    desc.shape_leg_length_m = shape.leg_length;
    desc.shape_leg_spacing_m = shape.leg_spacing;
    desc.shape_helix_radius_m = shape.helix_radius;
    desc.shape_helix_pitch_m = shape.helix_pitch;
    desc.integrator = static_cast<int32_t>(defaults.solver.integrator);
    desc.timestep_s = defaults.solver.timestep;
    desc.max_substeps = static_cast<uint32_t>(defaults.solver.max_substeps);
    desc.max_subdivisions = static_cast<uint32_t>(defaults.solver.max_subdivisions);
    desc.max_speed_m_per_s = defaults.solver.max_speed;
    desc.drag_N_s_per_m2 = damping.drag;
    desc.stretch_damping_N_s = damping.stretch;
    desc.bend_damping_N_m2_s = damping.bend;
    desc.mesentery_attachments = static_cast<uint32_t>(mesentery.attachments);
    desc.mesentery_stiffness_N_per_m = mesentery.stiffness;
    desc.mesentery_rest_length_m = mesentery.rest_length;
    desc.pinned_ends = scene::PinnedConfig{}.ends;
    desc.clamped_ends = scene::PinnedConfig{}.clamped;
    desc.collision_sphere_spacing_m = defaults.collision.sphere_spacing;
    desc.contact_stiffness_N_per_m = defaults.collision.contact.stiffness;
    desc.contact_damping_N_s_per_m = defaults.collision.contact.damping;
    desc.contact_friction = defaults.collision.contact.friction;
    desc.contact_slip_speed_m_per_s = defaults.collision.contact.slip_speed;
    return desc;
}

}  // namespace

// The sizes of ent_scene_desc in released headers. An older size is the offset of the first
// field its header lacks; those fields take their defaults.
//   0.0 preview  without `callbacks`. A simulated release: no 0.0 was published, but
//                tests/abi/enteron_v0_0.h keeps its header so that a test proves older
//                callers are served (tests/abi/old_caller.c).
//   0.1 first    without `clamped_ends`.
//   0.1          the current header.
void check_scene_desc_size(uint32_t struct_size) {
    check_struct_size(struct_size,
                      {offsetof(ent_scene_desc, callbacks), offsetof(ent_scene_desc, clamped_ends), sizeof(ent_scene_desc)},
                      "ent_scene_desc");
}

ent_scene_desc complete_desc(const ent_scene_desc& given) {
    check_scene_desc_size(given.struct_size);
    ent_scene_desc desc = default_desc();
    std::memcpy(&desc, &given, given.struct_size);
    return desc;
}

// The sizes of ent_callbacks in released headers: only the current one so far.
void check_callbacks_size(uint32_t struct_size) {
    check_struct_size(struct_size, {sizeof(ent_callbacks)}, "ent_callbacks");
}

void check_callbacks(const ent_callbacks& callbacks) {
    check_callbacks_size(callbacks.struct_size);
    if ((callbacks.allocate == nullptr) != (callbacks.release == nullptr))
        throw Error(ErrorCode::invalid_argument,
                    "ent_callbacks.allocate and ent_callbacks.release must be given together");
}

scene::SceneConfig config_from_desc(const ent_scene_desc& desc) {
    scene::SceneConfig config;
    const auto has = [&](int effect) { return (desc.effects & ENT_EFFECT_BIT(effect)) != 0; };
    // The effects a description turns on by bit; the environment starts with an obstacle,
    // the tools with a tool.
    constexpr uint32_t kDescEffects =
        ((1u << (ENT_EFFECT_PINNED + 1)) - 1u) | ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    if ((desc.effects & ~kDescEffects) != 0)
        throw Error(ErrorCode::invalid_argument,
                    "effects has bits of effects a description cannot turn on (environment starts with "
                    "ent_scene_add_obstacle, tools with ent_tool_add), got " + std::to_string(desc.effects));

    scene::IntestineConfig& intestine = config.intestine;
    intestine.length = desc.length_m;
    intestine.radius = desc.radius_m;
    intestine.control_points = desc.control_points;
    intestine.linear_density = desc.linear_density_kg_per_m;
    // Without its bit an elasticity is off, as a zero stiffness is.
    intestine.stretch_stiffness = has(ENT_EFFECT_STRETCH) ? desc.stretch_stiffness_N : 0.0;
    intestine.bend_stiffness = has(ENT_EFFECT_BEND) ? desc.bend_stiffness_N_m2 : 0.0;

    scene::ShapeConfig& shape = intestine.shape;
    shape.kind = static_cast<scene::ShapeKind>(desc.shape);
    shape.center = vec3(desc.shape_center_m);
    shape.direction = vec3(desc.shape_direction);
    shape.leg_length = desc.shape_leg_length_m;
    shape.leg_spacing = desc.shape_leg_spacing_m;
    shape.helix_radius = desc.shape_helix_radius_m;
    shape.helix_pitch = desc.shape_helix_pitch_m;
    if (desc.shape == ENT_SHAPE_POINTS && desc.control_points <= kMaxControlPoints) {
        require(desc.shape_points_xyz_m, "shape_points_xyz_m (with shape ENT_SHAPE_POINTS)");
        shape.points.assign(desc.shape_points_xyz_m, desc.shape_points_xyz_m + 3 * std::size_t{desc.control_points});
    }

    scene::SolverConfig& solver = config.solver;
    solver.integrator = static_cast<mechanics::IntegratorKind>(desc.integrator);
    solver.timestep = desc.timestep_s;
    solver.max_substeps = desc.max_substeps;
    solver.max_subdivisions = desc.max_subdivisions;
    solver.max_speed = desc.max_speed_m_per_s;

    if (has(ENT_EFFECT_GRAVITY)) config.gravity = vec3(desc.gravity_m_per_s2);
    if (has(ENT_EFFECT_DAMPING))
        config.damping = scene::DampingConfig{desc.drag_N_s_per_m2, desc.stretch_damping_N_s,
                                              desc.bend_damping_N_m2_s};
    if (has(ENT_EFFECT_MESENTERY))
        config.mesentery = scene::MesenteryConfig{vec3(desc.mesentery_root_start_m),
                                                  vec3(desc.mesentery_root_end_m),
                                                  desc.mesentery_attachments,
                                                  desc.mesentery_stiffness_N_per_m,
                                                  desc.mesentery_rest_length_m, std::nullopt};
    if (has(ENT_EFFECT_PINNED)) {
        scene::PinnedConfig pinned;
        pinned.ends = desc.pinned_ends;
        pinned.clamped = desc.clamped_ends;
        if (desc.pinned_point_count > 0) {
            if (desc.pinned_point_count > desc.control_points || desc.pinned_point_count > kMaxControlPoints)
                throw Error(ErrorCode::invalid_argument, "pinned_point_count must be <= control_points, got " +
                                                             std::to_string(desc.pinned_point_count));
            require(desc.pinned_points, "pinned_points (with pinned_point_count > 0)");
            pinned.points.assign(desc.pinned_points, desc.pinned_points + desc.pinned_point_count);
        }
        config.pinned = pinned;
    }
    config.self_collision = has(ENT_EFFECT_SELF_COLLISION);
    config.collision.sphere_spacing = desc.collision_sphere_spacing_m;
    config.collision.contact.stiffness = desc.contact_stiffness_N_per_m;
    config.collision.contact.damping = desc.contact_damping_N_s_per_m;
    config.collision.contact.friction = desc.contact_friction;
    config.collision.contact.slip_speed = desc.contact_slip_speed_m_per_s;
    const scene::FieldSet given = scene::fields_apart_from_defaults(config);
    return scene::validate(std::move(config), scene::c_field_names(), given);
}

}  // namespace enteron::capi

extern "C" {

ENT_API ent_status ent_callbacks_init(ent_callbacks* callbacks, uint32_t struct_size) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(callbacks, "callbacks");
        enteron::capi::check_callbacks_size(struct_size);
        ent_callbacks defaults;
        std::memset(&defaults, 0, sizeof defaults);
        defaults.struct_size = struct_size;
        std::memcpy(callbacks, &defaults, struct_size);
    });
}

ENT_API ent_status ent_scene_desc_init(ent_scene_desc* desc, uint32_t struct_size) {
    return enteron::capi::guarded([&] {
        enteron::capi::require(desc, "desc");
        enteron::capi::check_scene_desc_size(struct_size);
        ent_scene_desc defaults = enteron::capi::default_desc();
        defaults.struct_size = struct_size;
        // An older caller's struct ends at struct_size: write nothing past it.
        std::memcpy(desc, &defaults, struct_size);
    });
}

}  // extern "C"
