// SPDX-License-Identifier: Apache-2.0
#include "study_scenes.h"

#include <algorithm>
#include <cmath>

namespace study {

std::string pile_json(const PileSettings& s) {
    std::string tools;
    if (!s.tools_json.empty()) tools = ", \"tools\": " + s.tools_json;
    return format(
        "{\"intestine\": {\"length\": 6.0, \"radius\": %.17g, \"control_points\": %u,"
        " \"linear_density\": 0.3, \"stretch_stiffness\": 100, \"bend_stiffness\": 0.0025,"
        " \"shape\": {\"kind\": \"helix\", \"center\": [0, 0, -0.13], \"helix_radius\": 0.1,"
        " \"helix_pitch\": 0.025}},"
        " \"solver\": {\"integrator\": \"%s\", \"timestep\": %.17g},"
        " \"gravity\": [0, 0, -9.81],"
        " \"damping\": {\"drag\": 0.05, \"stretch\": 0.05, \"bend\": 0},"
        " \"mesentery\": {\"root\": [[-0.075, 0, 0], [0.075, 0, 0]], \"stiffness\": 5,"
        " \"attachments\": 60, \"rest_length\": 0},"
        " \"collision\": {\"sphere_spacing\": %.17g, \"stiffness\": %.17g},"
        " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0],"
        " \"half_extents\": [%.17g, %.17g, %.17g]}],"
        " \"self_collision\": {}%s}",
        kPileRadius, s.control_points, s.integrator, s.timestep_s, s.sphere_spacing_m,
        s.contact_stiffness_N_per_m, kPileBoxHalfExtent, kPileBoxHalfExtent, kPileBoxHalfExtent, tools.c_str());
}

std::vector<double> pile_sphere_spacings(const Options& options) {
    const double r = kPileRadius;
    if (options.tiny) return {r / 2};
    if (options.fast) return {r / 4, r / 2, r};
    return {r / 4, r / 2, 0.75 * r, r};
}

std::vector<double> pile_contact_stiffnesses(const Options& options) {
    if (options.tiny) return {500, 2000};
    if (options.fast) return {250, 500, 2000};
    return {125, 250, 500, 1000, 2000, 4000};
}

void Penetration::add(const Penetration& o) {
    max_m = std::max(max_m, o.max_m);
    sum_squares_m2 += o.sum_squares_m2;
    penetrating += o.penetrating;
    samples += o.samples;
}

double Penetration::rms_m() const {
    return penetrating ? std::sqrt(sum_squares_m2 / static_cast<double>(penetrating)) : 0.0;
}

Penetration measure_pile_penetration(const std::vector<double>& axis, double spacing_m) {
    constexpr double kPi = 3.14159265358979323846;
    const double r = kPileRadius;
    const std::size_t n = axis.size() / 3;
    // Samples closer along the axis than pi R are neighbours, not folds (the library's rule).
    const std::size_t window = static_cast<std::size_t>(std::ceil(kPi * r / spacing_m));
    Penetration out;
    out.samples = n;
    for (std::size_t i = 0; i < n; ++i) {
        const double* p = &axis[3 * i];
        double depth = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double to_wall = kPileBoxHalfExtent - std::fabs(p[c]);
            depth = std::max(depth, r - to_wall);
        }
        double nearest2 = 4.0 * r * r;
        for (std::size_t j = 0; j < n; ++j) {
            if ((i > j ? i - j : j - i) <= window) continue;
            const double* o = &axis[3 * j];
            const double dx = p[0] - o[0], dy = p[1] - o[1], dz = p[2] - o[2];
            nearest2 = std::min(nearest2, dx * dx + dy * dy + dz * dz);
        }
        depth = std::max(depth, 2.0 * r - std::sqrt(nearest2));
        if (depth > 0.0) {
            out.max_m = std::max(out.max_m, depth);
            out.sum_squares_m2 += depth * depth;
            out.penetrating += 1;
        }
    }
    return out;
}

}  // namespace study
