// SPDX-License-Identifier: Apache-2.0
// The two settled piles the skins are measured on (skin benchmark, accuracy study, tests),
// and how tightly each one bends. Through the public C API only.
//
//  - the demo's pile: the 6 m bowel of examples/demo.c dropped as a wide helix (radius 8 R)
//    into the 30 cm abdominal cavity, held by its mesentery, after 2 s. Its folds are
//    gentle: none of its axis bends with a radius under 4 R, its tightest U-turn about 6 R.
//  - the tight-fold pile: the same bowel, limp (a hundred-and-twenty-fifth of the bending
//    stiffness), 360 control points, released as a tight coil (radius 2.8 R, pitch 2.4 R)
//    into a tall box 30 cm wide with no mesentery; after 6 s it has collapsed into a pile
//    of loops where 83 % of the axis bends with a radius under 4 R (29 % under 2 R) and the
//    tightest U-turn has a mean radius of 1.43 R (bend_radii(), measured).
//
// bend_radii() measures that on any scene; the benchmark and the study print it, the tests
// check it.
#pragma once

#include <enteron/enteron.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace enteron::bench {

struct SkinPile {
    const char* name;         // for tables: "demo_pile", "tight_fold_pile"
    const char* json;         // the scene
    double settle_s;          // simulated before skinning, in 1 ms steps
};

// The demo's scene (examples/demo.c) without its tool.
inline constexpr SkinPile kDemoPile = {
    "demo_pile",
    "{\"intestine\": {\"length\": 6.0, \"radius\": 0.0125, \"control_points\": 240, \"linear_density\": 0.3,"
    " \"stretch_stiffness\": 100, \"bend_stiffness\": 2.5e-3,"
    " \"shape\": {\"kind\": \"helix\", \"center\": [0, 0, -0.13], \"helix_radius\": 0.1, \"helix_pitch\": 0.025}},"
    " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},"
    " \"gravity\": [0, 0, -9.81],"
    " \"damping\": {\"drag\": 0.05, \"stretch\": 0.05, \"bend\": 0},"
    " \"mesentery\": {\"root\": [[-0.075, 0, 0], [0.075, 0, 0]], \"stiffness\": 5, \"attachments\": 60,"
    " \"rest_length\": 0},"
    " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0], \"half_extents\": [0.15, 0.15, 0.15]}],"
    " \"self_collision\": {}}",
    2.0};

inline constexpr SkinPile kTightFoldPile = {
    "tight_fold_pile",
    "{\"intestine\": {\"length\": 6.0, \"radius\": 0.0125, \"control_points\": 360, \"linear_density\": 0.3,"
    " \"stretch_stiffness\": 100, \"bend_stiffness\": 2e-5,"
    " \"shape\": {\"kind\": \"helix\", \"center\": [0, 0, -0.435], \"helix_radius\": 0.035, \"helix_pitch\": 0.03}},"
    " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},"
    " \"gravity\": [0, 0, -9.81],"
    " \"damping\": {\"drag\": 0.05, \"stretch\": 0.05, \"bend\": 0},"
    " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0], \"half_extents\": [0.15, 0.15, 0.45]}],"
    " \"self_collision\": {}}",
    6.0};

inline constexpr SkinPile kSkinPiles[] = {kDemoPile, kTightFoldPile};

// Makes the pile's scene and steps it for its settling time. NULL on failure
// (ent_last_error() says why).
inline ent_scene* settle_pile(const SkinPile& pile) {
    ent_scene* scene = nullptr;
    if (ent_scene_create_json(pile.json, std::strlen(pile.json), &scene) != ENT_OK) return nullptr;
    const long steps = std::lround(pile.settle_s / 1e-3);
    for (long i = 0; i < steps; ++i) {
        if (ent_scene_step(scene, 1e-3) != ENT_OK) {
            ent_scene_destroy(scene);
            return nullptr;
        }
    }
    return scene;
}

// The box around the axis of `scene` (sampled every R / 8 or so): min x y z, max x y z, m.
inline void axis_bounds(const ent_scene* scene, double box[6]) {
    std::vector<double> points(3 * 2000);
    for (int c = 0; c < 3; ++c) box[c] = 1e300, box[c + 3] = -1e300;
    if (ent_scene_axis(scene, 2000, points.data()) != ENT_OK) return;
    for (std::size_t i = 0; i < 2000; ++i)
        for (int c = 0; c < 3; ++c) {
            box[c] = std::min(box[c], points[3 * i + std::size_t(c)]);
            box[c + 3] = std::max(box[c + 3], points[3 * i + std::size_t(c)]);
        }
}

// The skin's mesh view (ent_skin_mesh), or an empty one (vertex_count 0) on failure.
inline ent_mesh_view mesh_of(const ent_skin* skin) {
    ent_mesh_view view;
    std::memset(&view, 0, sizeof view);
    view.struct_size = sizeof view;
    if (ent_skin_mesh(skin, &view) != ENT_OK) view.vertex_count = 0;
    return view;
}

// A fold pressed by a tool in a small pile: a limp 0.6 m bowel released as a coil into a
// small box settles for 1.5 s into loops resting on each other; a vertical tool then
// comes down on the highest point of its axis and presses, with 8 N, 4 R down over 0.3 s
// and holds for 0.2 s. The tool's tip (its last commanded position) in `tip`. NULL on
// failure (ent_last_error() says why).
inline ent_scene* pressed_small_pile(double tip[3]) {
    static const char json[] =
        "{\"intestine\": {\"length\": 0.6, \"radius\": 0.0125, \"control_points\": 48, \"linear_density\": 0.3,"
        " \"stretch_stiffness\": 100, \"bend_stiffness\": 2e-5,"
        " \"shape\": {\"kind\": \"helix\", \"center\": [0, 0, 0.05], \"helix_radius\": 0.03, \"helix_pitch\": 0.03}},"
        " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001}, \"gravity\": [0, 0, -9.81],"
        " \"damping\": {\"drag\": 0.05, \"stretch\": 0.05, \"bend\": 0},"
        " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0.1], \"half_extents\": [0.06, 0.06, 0.1]}],"
        " \"self_collision\": {}}";
    const double radius = 0.0125;
    ent_scene* scene = nullptr;
    if (ent_scene_create_json(json, sizeof json - 1, &scene) != ENT_OK) return nullptr;
    const auto fail = [&] {
        ent_scene_destroy(scene);
        return nullptr;
    };
    for (int i = 0; i < 1500; ++i)
        if (ent_scene_step(scene, 1e-3) != ENT_OK) return fail();
    std::vector<double> axis(3 * 400);
    if (ent_scene_axis(scene, 400, axis.data()) != ENT_OK) return fail();
    double top[3] = {0.0, 0.0, -1e300};
    for (std::size_t i = 0; i < axis.size(); i += 3)
        if (axis[i + 2] > top[2]) std::copy(&axis[i], &axis[i] + 3, top);
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    tool.max_force_N = 8.0;
    std::copy(top, top + 3, tool.position_m);
    tool.position_m[2] += 2.0 * radius;
    int32_t id = -1;
    if (ent_tool_add(scene, &tool, &id) != ENT_OK) return fail();
    const double identity[4] = {1.0, 0.0, 0.0, 0.0};
    for (int i = 1; i <= 500; ++i) {
        tip[0] = top[0];
        tip[1] = top[1];
        tip[2] = top[2] + 2.0 * radius - 4.0 * radius * std::min(1.0, i / 300.0);
        if (ent_tool_set_pose(scene, id, tip, identity) != ENT_OK || ent_scene_step(scene, 1e-3) != ENT_OK) return fail();
    }
    return scene;
}

// How tightly an axis bends, in units of the bowel's radius R.
struct BendRadii {
    static constexpr double kThresholds[] = {1.5, 2.0, 3.0, 4.0, 8.0};  // in R
    double fraction_under[5] = {};  // of the axis' length bending with a radius under each threshold
    double smallest = 0.0;          // the smallest radius of curvature, in R
    double tightest_u_turn = 0.0;   // the smallest mean radius of a half turn (arc length / pi), in R
};

// Measures the axis of `scene` sampled every R / 8 in arc length: the radius of curvature
// from second differences of the samples (1 / |x_{i+1} - 2 x_i + x_{i-1}| h^2, accurate to
// about (h / rho)^2 / 12), and the U-turns as the shortest arcs over which the tangent
// reverses (turns by 180 degrees, each at most 8 pi R long). Empty on failure.
inline BendRadii bend_radii(const ent_scene* scene, double radius_m) {
    BendRadii out;
    // The length first, from a coarse sampling, then the real one.
    std::vector<double> coarse(3 * 1001);
    if (ent_scene_axis(scene, 1001, coarse.data()) != ENT_OK) return out;
    double length = 0.0;
    for (std::size_t i = 1; i < 1001; ++i) {
        const double dx = coarse[3 * i] - coarse[3 * i - 3], dy = coarse[3 * i + 1] - coarse[3 * i - 2],
                     dz = coarse[3 * i + 2] - coarse[3 * i - 1];
        length += std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    const uint32_t count = static_cast<uint32_t>(std::ceil(length / (radius_m / 8.0))) + 1;
    std::vector<double> points(3 * std::size_t(count));
    if (ent_scene_axis(scene, count, points.data()) != ENT_OK) return out;
    const double h = length / double(count - 1);
    out.smallest = 1e300;
    std::vector<double> tangents(3 * std::size_t(count));
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t a = i > 0 ? i - 1 : i, b = i + 1 < count ? i + 1 : i;
        double t[3], norm = 0.0;
        for (int c = 0; c < 3; ++c) {
            t[c] = points[3 * b + c] - points[3 * a + c];
            norm += t[c] * t[c];
        }
        for (int c = 0; c < 3; ++c) tangents[3 * i + c] = norm > 0.0 ? t[c] / std::sqrt(norm) : 0.0;
        if (i == 0 || i + 1 == count) continue;
        double second = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double d = points[3 * (i + 1) + c] - 2.0 * points[3 * i + c] + points[3 * (i - 1) + c];
            second += d * d;
        }
        const double rho = second > 0.0 ? h * h / std::sqrt(second) / radius_m : 1e300;
        out.smallest = std::min(out.smallest, rho);
        for (std::size_t k = 0; k < 5; ++k)
            if (rho < BendRadii::kThresholds[k]) out.fraction_under[k] += 1.0 / double(count - 2);
    }
    out.tightest_u_turn = 1e300;
    const auto reach = static_cast<uint32_t>(std::ceil(8.0 * 3.14159265358979323846 * radius_m / h));
    for (uint32_t i = 0; i < count; ++i) {
        for (uint32_t j = i + 1; j < count && j <= i + reach; ++j) {
            const double dot = tangents[3 * i] * tangents[3 * j] + tangents[3 * i + 1] * tangents[3 * j + 1] +
                               tangents[3 * i + 2] * tangents[3 * j + 2];
            if (dot <= -1.0 + 1e-3) {  // reversed (within 2.6 degrees)
                out.tightest_u_turn = std::min(out.tightest_u_turn, double(j - i) * h / 3.14159265358979323846 / radius_m);
                break;
            }
        }
    }
    return out;
}

}  // namespace enteron::bench
