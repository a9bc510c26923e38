// SPDX-License-Identifier: Apache-2.0
// The 6 m small bowel that the step benchmarks share, as a C description, and small
// helpers around the C API. Through the public header only.
#pragma once

#include <enteron/enteron.h>

#include <cstdint>
#include <string>

namespace enteron::bench {

constexpr double kStepS = 1e-3;  // one ent_scene_step, s

struct Integrator {
    const char* name;
    int32_t id;
};
constexpr Integrator kIntegrators[] = {
    {"rk4", ENT_INTEGRATOR_RK4},
    {"symplectic_euler", ENT_INTEGRATOR_SYMPLECTIC_EULER},
    {"implicit_euler", ENT_INTEGRATOR_IMPLICIT_EULER},
    {"bdf2", ENT_INTEGRATOR_BDF2},
};

// "call: status: message" of a failed call on this thread.
inline std::string last_error(const char* call, ent_status status) {
    return std::string(call) + ": " + ent_status_string(status) + ": " + ent_last_error();
}

// 6 m, R = 12.5 mm, 0.3 kg/m, EA = 100 N, EI = 2.5e-3 N m^2, a vertical helix of radius
// 10 cm rising from helix_base_z_m with the given pitch, 1 ms steps, no pinned ends.
inline ent_scene_desc bowel_desc(int32_t integrator, uint32_t control_points, uint32_t effects,
                                 double helix_base_z_m, double helix_pitch_m) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.effects = effects;
    desc.length_m = 6.0;
    desc.radius_m = 0.0125;
    desc.linear_density_kg_per_m = 0.3;
    desc.control_points = control_points;
    desc.stretch_stiffness_N = 100.0;
    desc.bend_stiffness_N_m2 = 2.5e-3;
    desc.shape = ENT_SHAPE_HELIX;
    desc.shape_center_m[0] = 0.0;
    desc.shape_center_m[1] = 0.0;
    desc.shape_center_m[2] = helix_base_z_m;
    desc.shape_helix_radius_m = 0.1;
    desc.shape_helix_pitch_m = helix_pitch_m;
    desc.integrator = integrator;
    desc.timestep_s = kStepS;
    desc.pinned_ends = ENT_PIN_NONE;
    return desc;
}

inline bool read_stats(const ent_scene* scene, ent_stats* stats) {
    *stats = ent_stats{};
    stats->struct_size = sizeof(ent_stats);
    return ent_scene_stats(scene, stats) == ENT_OK;
}

}  // namespace enteron::bench
