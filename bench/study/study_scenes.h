// SPDX-License-Identifier: Apache-2.0
// The scenes shared by the collision, skin and effect parts of the study.
#pragma once

#include "study_common.h"

namespace study {

// The dense pile of the demo: the 6 m bowel (240 control points) dropped as a helix into
// the abdominal cavity (the inside of a 30 cm box), held by its mesentery, its folds
// piling on each other (self-collision). Implicit Euler, 1 ms.
struct PileSettings {
    double sphere_spacing_m = 0.0;      // 0: the library's default (R / 2)
    double contact_stiffness_N_per_m = 500.0;
    uint32_t control_points = 240;
    const char* integrator = "implicit_euler";
    double timestep_s = 1e-3;
    std::string tools_json;             // "" or a JSON array for the "tools" key
};
constexpr double kPileRadius = 0.0125;          // m
constexpr double kPileBoxHalfExtent = 0.15;     // m, the box is centred on the origin
std::string pile_json(const PileSettings& settings);

// The collision knobs of the study: sphere spacings from R/4 to R (m) and contact
// stiffnesses (N/m); fewer in fast mode, fewest in tiny mode.
std::vector<double> pile_sphere_spacings(const Options& options);
std::vector<double> pile_contact_stiffnesses(const Options& options);

// Geometric penetration of the tube (radius R) into the box walls and into itself,
// measured on the axis sampled every `spacing` (independent of the collision spheres):
// for each sample the deepest overlap with a wall (R - distance to the wall) or with a
// part of the axis more than pi R away along it (2R - distance).
struct Penetration {
    double max_m = 0.0;
    double sum_squares_m2 = 0.0;  // over penetrating samples
    uint64_t penetrating = 0;     // samples with an overlap
    uint64_t samples = 0;
    void add(const Penetration& other);
    double rms_m() const;         // RMS over the penetrating samples (0 if none)
};
Penetration measure_pile_penetration(const std::vector<double>& axis, double spacing_m);

}  // namespace study
