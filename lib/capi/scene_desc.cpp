// SPDX-License-Identifier: Apache-2.0
#include "capi/scene_desc.h"

#include <cstddef>
#include <cstring>
#include <utility>

#include "capi/call_guard.h"
#include "capi/desc_fields.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "scene/validate.h"

namespace enteron::capi {

namespace {

// Larger inputs than these are refused before anything is copied from the caller's arrays.
constexpr uint32_t kMaxControlPoints = 100000;
constexpr uint32_t kMaxProfilePairs = 100000;

// An array of `count` tuples of `width` doubles (ent_scene_desc: pointer and count, named
// `count_name`) into `values`.
void read_tuples(const double* given, uint32_t count, std::size_t width, const char* name, const char* count_name,
                 std::vector<double>& values) {
    if (count == 0) return;
    if (count > kMaxProfilePairs)
        throw Error(ErrorCode::invalid_argument, std::string(count_name) + " must be <= " +
                                                     std::to_string(kMaxProfilePairs) + ", got " + std::to_string(count));
    require(given, (std::string(name) + " (with " + count_name + " > 0)").c_str());
    values.assign(given, given + width * std::size_t{count});
}

// A profile's pairs (ent_scene_desc: pointer and count) into `pairs`.
void read_profile(const double* given, uint32_t count, const char* name, std::vector<double>& pairs) {
    read_tuples(given, count, 2, name, (std::string(name) + "_count").c_str(), pairs);
}

// An array given for an effect whose bit is clear is a mistake, not a wish.
void require_effect(bool on, uint32_t count, const char* name, const char* effect) {
    if (count > 0 && !on)
        throw Error(ErrorCode::invalid_argument,
                    std::string(name) + " is given, but effects leaves " + effect + " off: set its bit or leave it NULL");
}

// The fields of ent_scene_desc that are values of the scene's table, each the row of its
// name (scene/scene_table.cpp). The others: struct_size, effects, the arrays and their
// counts, callbacks.
#define SCENE_FIELD(field) ENTERON_DESC_FIELD(ent_scene_desc, field)
const DescField<ent_scene_desc> kSceneDescFields[] = {
    SCENE_FIELD(length_m), SCENE_FIELD(radius_m), SCENE_FIELD(control_points), SCENE_FIELD(linear_density_kg_per_m),
    SCENE_FIELD(stretch_stiffness_N), SCENE_FIELD(bend_stiffness_N_m2),
    SCENE_FIELD(shape), SCENE_FIELD(shape_center_m), SCENE_FIELD(shape_direction), SCENE_FIELD(shape_leg_length_m),
    SCENE_FIELD(shape_leg_spacing_m), SCENE_FIELD(shape_helix_radius_m), SCENE_FIELD(shape_helix_pitch_m),
    SCENE_FIELD(integrator), SCENE_FIELD(timestep_s), SCENE_FIELD(max_substeps), SCENE_FIELD(max_subdivisions),
    SCENE_FIELD(max_speed_m_per_s),
    SCENE_FIELD(gravity_m_per_s2),
    SCENE_FIELD(drag_N_s_per_m2), SCENE_FIELD(stretch_damping_N_s), SCENE_FIELD(bend_damping_N_m2_s),
    SCENE_FIELD(mesentery_root_start_m), SCENE_FIELD(mesentery_root_end_m), SCENE_FIELD(mesentery_attachments),
    SCENE_FIELD(mesentery_stiffness_N_per_m), SCENE_FIELD(mesentery_rest_length_m),
    SCENE_FIELD(pinned_ends), SCENE_FIELD(clamped_ends),
    SCENE_FIELD(collision_sphere_spacing_m), SCENE_FIELD(contact_stiffness_N_per_m),
    SCENE_FIELD(contact_damping_N_s_per_m), SCENE_FIELD(contact_friction), SCENE_FIELD(contact_slip_speed_m_per_s),
};
#undef SCENE_FIELD

const DescBinding<ent_scene_desc>& scene_desc_fields() {
    static const DescBinding<ent_scene_desc> binding(scene::scene_block(), kSceneDescFields);
    return binding;
}

// The effects a description turns on by bit; the environment starts with an obstacle,
// the tools with a tool.
constexpr uint32_t kDescEffects = ((1u << (ENT_EFFECT_PINNED + 1)) - 1u) | ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);

// config with every effect a description can turn on present, those it leaves off at their
// defaults (gravity the Earth's): what a desc's fields show whatever its bits.
scene::SceneConfig with_every_effect(scene::SceneConfig config) {
    if (!config.gravity) config.gravity = scene::kStandardGravity;
    if (!config.damping) config.damping.emplace();
    if (!config.mesentery) config.mesentery.emplace();
    if (!config.pinned) config.pinned.emplace();
    return config;
}

}  // namespace

ent_scene_desc desc_from_config(const scene::SceneConfig& config) {
    ent_scene_desc desc;
    std::memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc;
    const scene::SceneConfig all = with_every_effect(config);
    scene_desc_fields().write(&all, desc);
    const auto bit = [](bool on, int effect) { return on ? ENT_EFFECT_BIT(effect) : 0u; };
    desc.effects = bit(config.intestine.stretch_stiffness != 0.0, ENT_EFFECT_STRETCH) |
                   bit(config.intestine.bend_stiffness != 0.0, ENT_EFFECT_BEND) |
                   bit(config.damping.has_value(), ENT_EFFECT_DAMPING) |
                   bit(config.gravity.has_value(), ENT_EFFECT_GRAVITY) |
                   bit(config.mesentery.has_value(), ENT_EFFECT_MESENTERY) |
                   bit(config.pinned.has_value(), ENT_EFFECT_PINNED) |
                   bit(config.self_collision, ENT_EFFECT_SELF_COLLISION);
    return desc;
}

namespace {

// The defaults of the current ent_scene_desc, whole: those of a default SceneConfig (one
// set for JSON and C), with gravity and damping turned on.
ent_scene_desc default_desc() {
    scene::SceneConfig defaults;
    defaults.gravity = scene::kStandardGravity;
    defaults.damping.emplace();
    return desc_from_config(defaults);
}

}  // namespace

// The sizes of ent_scene_desc in released headers. An older size is the offset of the first
// field its header lacks; those fields take their defaults.
//   0.0 preview  without `callbacks`. A simulated release: no 0.0 was published, but
//                tests/abi/enteron_v0_0.h keeps its header so that a test proves older
//                callers are served (tests/abi/old_caller.c).
//   0.1 first    without `clamped_ends`.
//   0.1 second   without the profiles (radius_profile_m ...).
//   0.1 third    without the fan mesentery and the pinned spans (mesentery_root_points_m ...).
//   0.1          the current header.
void check_scene_desc_size(uint32_t struct_size) {
    check_struct_size(struct_size,
                      {offsetof(ent_scene_desc, callbacks), offsetof(ent_scene_desc, clamped_ends),
                       offsetof(ent_scene_desc, radius_profile_m), offsetof(ent_scene_desc, mesentery_root_points_m),
                       sizeof(ent_scene_desc)},
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
    if ((desc.effects & ~kDescEffects) != 0)
        throw Error(ErrorCode::invalid_argument,
                    "effects has bits of effects a description cannot turn on (environment starts with "
                    "ent_scene_add_obstacle, tools with ent_tool_add), got " + std::to_string(desc.effects));
    if (has(ENT_EFFECT_GRAVITY)) config.gravity.emplace();
    if (has(ENT_EFFECT_DAMPING)) config.damping.emplace();
    if (has(ENT_EFFECT_MESENTERY)) config.mesentery.emplace();
    if (has(ENT_EFFECT_PINNED)) config.pinned.emplace();
    config.self_collision = has(ENT_EFFECT_SELF_COLLISION);
    scene_desc_fields().read(desc, &config);

    scene::IntestineConfig& intestine = config.intestine;
    // Without its bit an elasticity is off, as a zero stiffness is.
    if (!has(ENT_EFFECT_STRETCH)) intestine.stretch_stiffness = 0.0;
    if (!has(ENT_EFFECT_BEND)) intestine.bend_stiffness = 0.0;
    if (desc.shape == ENT_SHAPE_POINTS && desc.control_points <= kMaxControlPoints) {
        require(desc.shape_points_xyz_m, "shape_points_xyz_m (with shape ENT_SHAPE_POINTS)");
        intestine.shape.points.assign(desc.shape_points_xyz_m,
                                      desc.shape_points_xyz_m + 3 * std::size_t{desc.control_points});
    }
    if (config.pinned && desc.pinned_point_count > 0) {
        if (desc.pinned_point_count > desc.control_points || desc.pinned_point_count > kMaxControlPoints)
            throw Error(ErrorCode::invalid_argument, "pinned_point_count must be <= control_points, got " +
                                                         std::to_string(desc.pinned_point_count));
        require(desc.pinned_points, "pinned_points (with pinned_point_count > 0)");
        config.pinned->points.assign(desc.pinned_points, desc.pinned_points + desc.pinned_point_count);
    }
    read_profile(desc.radius_profile_m, desc.radius_profile_count, "radius_profile_m", intestine.radius_profile);
    read_profile(desc.linear_density_profile_kg_per_m, desc.linear_density_profile_count,
                 "linear_density_profile_kg_per_m", intestine.linear_density_profile);
    read_profile(desc.stretch_stiffness_profile_N, desc.stretch_stiffness_profile_count,
                 "stretch_stiffness_profile_N", intestine.stretch_stiffness_profile);
    read_profile(desc.bend_stiffness_profile_N_m2, desc.bend_stiffness_profile_count, "bend_stiffness_profile_N_m2",
                 intestine.bend_stiffness_profile);
    require_effect(config.mesentery.has_value(), desc.mesentery_root_point_count, "mesentery_root_points_m",
                   "ENT_EFFECT_MESENTERY");
    require_effect(config.mesentery.has_value(), desc.mesentery_root_mapping_count, "mesentery_root_mapping",
                   "ENT_EFFECT_MESENTERY");
    require_effect(config.pinned.has_value(), desc.pinned_span_count, "pinned_spans_m", "ENT_EFFECT_PINNED");
    if (config.mesentery) {
        read_tuples(desc.mesentery_root_points_m, desc.mesentery_root_point_count, 3, "mesentery_root_points_m",
                    "mesentery_root_point_count", config.mesentery->root_points);
        read_profile(desc.mesentery_root_mapping, desc.mesentery_root_mapping_count, "mesentery_root_mapping",
                     config.mesentery->root_mapping);
    }
    if (config.pinned) {
        std::vector<double> spans;
        read_tuples(desc.pinned_spans_m, desc.pinned_span_count, 2, "pinned_spans_m", "pinned_span_count", spans);
        for (std::size_t k = 0; k < spans.size() / 2; ++k)
            config.pinned->spans.push_back({spans[2 * k], spans[2 * k + 1], std::nullopt});
    }
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

ENT_API ent_status ent_scene_read_desc(const ent_scene* scene, ent_scene_desc* out) {
    return enteron::capi::guarded([&] {
        const enteron::capi::SceneCall call(scene);
        const enteron::capi::SceneHandle& handle = call.handle();
        enteron::capi::require(out, "out");
        enteron::capi::check_scene_desc_size(out->struct_size);
        ent_scene_desc desc = handle.description;
        desc.struct_size = out->struct_size;
        // An older caller's struct ends at struct_size: write nothing past it.
        std::memcpy(out, &desc, out->struct_size);
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
