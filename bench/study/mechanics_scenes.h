// SPDX-License-Identifier: Apache-2.0
// The scenes and the grid of settings of the mechanics part of the study, shared with the
// peers part (the same scenes in other engines, bench/peers): one definition of the bowel,
// of each scene and of the N and time-step sweeps, so that a peer runs exactly what we run.
#pragma once

#include "study_common.h"

namespace study {

// The bowel of every mechanics scene: the whole small bowel, pinned at its first end (or
// both), starting straight and horizontal along +x from the origin, at rest.
struct MechanicsBowel {
    double length_m = 6.0;
    double radius_m = 0.0125;
    double linear_density_kg_per_m = 0.3;
    double stretch_stiffness_N = 100.0;        // EA
    double bend_stiffness_N_m2 = 2.5e-3;       // EI
    // Drag of every scene, N s/m^2. The library's light default (0.05) lets the free end of
    // a 6 m bowel whip: measured, the swing's state at 2 s then does not converge with N up
    // to 960 (the distance between N and 2N stalls near 7 mm). Tissue around the bowel damps
    // it far more than that anyway.
    double drag_N_s_per_m2 = 1.0;
    double stretch_damping_N_s = 0.05;         // axial force per unit strain rate
    double bend_damping_N_m2_s = 0.0;
    double gravity_m_per_s2 = 9.81;            // along -z
    double floor_depth_m = 0.5;                // below the pin (drop)
};
inline constexpr MechanicsBowel kMechanicsBowel{};

// swing: pinned at its first end, released from horizontal, swinging down;
// sag:   pinned at both ends, straight and horizontal at first, sagging under gravity to rest;
// drop:  the swing with a floor kMechanicsBowel.floor_depth_m below the pin: the bowel
//        drops onto the plane.
enum class MechanicsScene { swing, sag, drop };
const char* mechanics_scene_name(MechanicsScene scene);
std::string mechanics_scene_json(MechanicsScene scene, uint32_t control_points, int32_t integrator, double timestep_s);

// Axis samples (evenly spaced in arc length) of every error of the mechanics study.
constexpr uint32_t kAxisSamples = 201;
constexpr double kOneMs = 1e-3;  // the step of a 1 kHz loop, s

// What the mechanics study runs, fast (ctest) or full (the committed results).
struct MechanicsGrid {
    std::vector<double> times_s;          // when the axes are compared
    std::vector<uint32_t> sizes;          // N sweep, at 1 ms
    uint32_t reference_points = 0;        // the reference: rk4 at N and time step below
    int32_t reference_integrator = ENT_INTEGRATOR_RK4;
    double reference_timestep_s = 0.0;
    uint32_t dt_sweep_points = 0;         // N of the time-step sweep
    std::vector<double> timesteps_s;      // time-step sweep
    std::vector<MechanicsScene> scenes;
};
MechanicsGrid mechanics_grid(const Options& options);

}  // namespace study
