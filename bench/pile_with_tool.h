// SPDX-License-Identifier: Apache-2.0
// The demo pile with a tool, shared by the benchmarks that time it (collision_bench.cpp,
// tail_bench.cpp): the demo's 6 m bowel (examples/demo_scene.h) with every effect (stretch,
// bend, damping, gravity, mesentery, self-collision with spheres every R / 2) dropped as a
// helix near the floor of the abdominal cavity (the inside of a 30 cm box), settled for
// 2 s with implicit Euler; then a grasper (the default tool, 5 mm shaft) held 5 mm into the
// pile above its highest control point, following that point and sliding 1 cm back and
// forth along x at 1 Hz (friction drags the surface), its pose set before every step from
// the last published state, as a haptic loop would. Through the C API only.
#pragma once

#include <enteron/enteron.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bowel_scene.h"

namespace enteron::bench {

constexpr double kPileSettleS = 2.0;
constexpr double kCavityHalfExtentM = 0.15;

// The demo's bowel with N control points (examples/demo.c): every effect; the box comes with
// cavity_desc(). Collision spheres every R / 2 (the default spacing 0).
inline ent_scene_desc pile_bowel_desc(int32_t integrator, uint32_t control_points) {
    return bowel_desc(integrator, control_points,
                      ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                          ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                          ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION),
                      -0.13, 0.025);
}

inline ent_obstacle_desc cavity_desc() {
    ent_obstacle_desc box;
    ent_obstacle_desc_default(&box);
    box.kind = ENT_OBSTACLE_BOX_INSIDE;
    for (int c = 0; c < 3; ++c) {
        box.center_m[c] = 0.0;
        box.half_extents_m[c] = kCavityHalfExtentM;
    }
    return box;
}

// The bowel in the cavity; settle_steps steps of kStepS taken. Returns nullptr (and the
// message) on failure. `points`, if not empty, is the initial shape (N x 3, m).
inline ent_scene* bowel_in_cavity(int32_t integrator, uint32_t control_points, const std::vector<double>& points,
                                  int settle_steps, std::string* error) {
    ent_scene_desc desc = pile_bowel_desc(integrator, control_points);
    if (!points.empty()) {
        desc.shape = ENT_SHAPE_POINTS;
        desc.shape_points_xyz_m = points.data();
    }
    ent_scene* scene = nullptr;
    ent_status status = ent_scene_create(&desc, &scene);
    if (status != ENT_OK) {
        *error = last_error("ent_scene_create", status);
        return nullptr;
    }
    const ent_obstacle_desc box = cavity_desc();
    status = ent_scene_add_obstacle(scene, &box, nullptr);
    if (status != ENT_OK) {
        *error = last_error("ent_scene_add_obstacle", status);
        ent_scene_destroy(scene);
        return nullptr;
    }
    for (int i = 0; i < settle_steps; ++i) {
        status = ent_scene_step(scene, kStepS);
        if (status != ENT_OK) {
            *error = last_error("ent_scene_step (settling)", status);
            ent_scene_destroy(scene);
            return nullptr;
        }
    }
    return scene;
}

// The control points of the bowel settled with implicit Euler, once per N (shared by every
// caller with that N). Empty, with the message in *error, on failure.
inline const std::vector<double>& settled_pile(uint32_t control_points, std::string* error) {
    static std::vector<std::pair<uint32_t, std::vector<double>>> piles;
    for (const auto& [n, points] : piles)
        if (n == control_points) return points;
    std::vector<double> points;
    const int settle_steps = static_cast<int>(std::lround(kPileSettleS / kStepS));
    ent_scene* scene = bowel_in_cavity(ENT_INTEGRATOR_IMPLICIT_EULER, control_points, {}, settle_steps, error);
    if (scene != nullptr) {
        points.resize(3 * static_cast<std::size_t>(control_points));
        uint32_t count = 0;
        const ent_status status = ent_scene_control_points(scene, control_points, points.data(), &count);
        if (status != ENT_OK) {
            *error = last_error("ent_scene_control_points", status);
            points.clear();
        }
        ent_scene_destroy(scene);
    }
    if (points.empty()) {
        static const std::vector<double> none;
        return none;
    }
    piles.emplace_back(control_points, std::move(points));
    return piles.back().second;
}

// The tool pressed into the pile: its tip above the pile's highest control point by the two
// radii less kPressM, sliding kSweepM along x at kSweepHz.
class PileTool {
public:
    static constexpr double kPressM = 0.005;
    static constexpr double kSweepM = 0.01;
    static constexpr double kSweepHz = 1.0;

    // For the settled `pile` of a bowel of radius bowel_radius_m and a tool of radius tool_radius_m.
    PileTool(const std::vector<double>& pile, double bowel_radius_m, double tool_radius_m)
        : held_(highest_point(pile)), reach_m_(bowel_radius_m + tool_radius_m - kPressM) {}

    // The tip at time_s over the held point of `points` (the control points, N x 3, m); the
    // shaft rises from it along +z.
    void position_at(const std::vector<double>& points, double time_s, double position_m[3]) const {
        constexpr double kPi = 3.14159265358979323846;
        position_m[0] = points[3 * held_] + kSweepM * std::sin(2.0 * kPi * kSweepHz * time_s);
        position_m[1] = points[3 * held_ + 1];
        position_m[2] = points[3 * held_ + 2] + reach_m_;
    }

private:
    static std::size_t highest_point(const std::vector<double>& points) {
        std::size_t top = 0;
        for (std::size_t i = 0; 3 * i < points.size(); ++i)
            if (points[3 * i + 2] > points[3 * top + 2]) top = i;
        return top;
    }

    std::size_t held_;
    double reach_m_;
};

}  // namespace enteron::bench
