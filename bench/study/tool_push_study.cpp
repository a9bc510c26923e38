// Collision accuracy at the tool: a grasper shaft pushed into the settled pile.
//
// The pile (study_scenes.h) with one tool (JSON "tools": radius 5 mm, 30 cm shaft, 8 N
// bound) parked straight above the cavity, settles for kSettle; then the tool's tip is
// placed 2 cm above the highest part of the bowel under it and pushed straight down at
// 5 cm/s for 0.8 s (4 cm), then held for 0.2 s, one ent_tool_set_pose per 1 ms step.
// Every step: the penetration of the tube into the tool capsule, measured on the axis
// sampled every R/8 (R + tool radius - distance from the axis point to the shaft
// segment), and the force on the tool (ent_tool_wrench). Reported: max and RMS
// penetration over the push, the largest force, and the force's step-to-step change
// |F(k) - F(k-1)| (max and RMS): what a haptic device feels as roughness.
#include "tool_push_study.h"

#include "study_scenes.h"

#include <algorithm>
#include <cmath>

namespace study {

namespace {

constexpr double kToolRadius = 0.005;   // m
constexpr double kToolLength = 0.3;     // m
constexpr double kToolMaxForce = 8.0;   // N
constexpr double kToolX = 0.1, kToolY = 0.0;  // m, over the coil of the helix
constexpr double kParkZ = 0.5;          // m, above the cavity (0.15)

double distance_to_segment(const double* p, const double a[3], const double b[3]) {
    double ab[3], ap[3];
    for (int c = 0; c < 3; ++c) {
        ab[c] = b[c] - a[c];
        ap[c] = p[c] - a[c];
    }
    const double length2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    const double t = length2 > 0 ? std::clamp((ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / length2, 0.0, 1.0) : 0.0;
    double d2 = 0;
    for (int c = 0; c < 3; ++c) d2 += (ap[c] - t * ab[c]) * (ap[c] - t * ab[c]);
    return std::sqrt(d2);
}

}  // namespace

void run_tool_push_study(const Options& options) {
    const double r = kPileRadius;
    const std::vector<double> spacings = pile_sphere_spacings(options);
    const std::vector<double> stiffnesses = pile_contact_stiffnesses(options);
    const double settle_s = options.fast ? 1.0 : 2.0;
    const double step_s = 1e-3;
    const double speed = 0.05, push_s = 0.8, hold_s = 0.2, clearance = 0.02;
    const double sample_spacing = r / 8;
    const uint32_t samples = static_cast<uint32_t>(std::lround(6.0 / sample_spacing)) + 1;
    const double identity[4] = {1, 0, 0, 0};

    Csv csv(options.out_dir + "/collision_tool.csv",
            {"sphere_spacing_m", "sphere_spacing_radii", "contact_stiffness_N_per_m", "max_penetration_m",
             "rms_penetration_m", "max_force_N", "tool_max_force_N", "force_jump_max_N", "force_jump_rms_N",
             "push_depth_m", "us_per_ms", "rollbacks", "status"});
    for (double spacing : spacings)
        for (double stiffness : stiffnesses) {
            PileSettings settings;
            settings.sphere_spacing_m = spacing;
            settings.contact_stiffness_N_per_m = stiffness;
            settings.tools_json = format("[{\"radius\": %.17g, \"length\": %.17g, \"max_force\": %.17g,"
                                         " \"position\": [%.17g, %.17g, %.17g], \"orientation\": [1, 0, 0, 0]}]",
                                         kToolRadius, kToolLength, kToolMaxForce, kToolX, kToolY, kParkZ);
            double max_pen = 0, sum_pen2 = 0, max_force = 0, jump_max = 0, jump_sum2 = 0, us = std::nan("");
            uint64_t pen_count = 0, jumps = 0, rollbacks = 0;
            std::string status = "ok";
            const double start = now_s();
            try {
                ScenePtr scene = make_scene(pile_json(settings));
                for (long k = 0; k < std::lround(settle_s / step_s); ++k)
                    check(ent_scene_step(scene.get(), step_s), "ent_scene_step");
                // The highest part of the bowel under the tool.
                const std::vector<double> axis = sample_axis(scene.get(), samples);
                double top = -kPileBoxHalfExtent;
                for (uint32_t i = 0; i < samples; ++i) {
                    const double dx = axis[3 * i] - kToolX, dy = axis[3 * i + 1] - kToolY;
                    if (std::sqrt(dx * dx + dy * dy) < r + kToolRadius) top = std::max(top, axis[3 * i + 2]);
                }
                double tip[3] = {kToolX, kToolY, top + r + kToolRadius + clearance};
                check(ent_tool_set_pose(scene.get(), 0, tip, identity), "ent_tool_set_pose");
                check(ent_scene_step(scene.get(), step_s), "ent_scene_step");  // the move down from the park
                double previous[3] = {0, 0, 0}, torque[3];
                check(ent_tool_wrench(scene.get(), 0, previous, torque), "ent_tool_wrench");
                std::vector<double> times;
                const long steps = std::lround((push_s + hold_s) / step_s);
                for (long k = 1; k <= steps; ++k) {
                    if (k <= std::lround(push_s / step_s)) tip[2] -= speed * step_s;
                    check(ent_tool_set_pose(scene.get(), 0, tip, identity), "ent_tool_set_pose");
                    const double t0 = now_s();
                    check(ent_scene_step(scene.get(), step_s), "ent_scene_step");
                    times.push_back((now_s() - t0) * 1e6);
                    double force[3];
                    check(ent_tool_wrench(scene.get(), 0, force, torque), "ent_tool_wrench");
                    const double magnitude = std::sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
                    const double jump = std::sqrt((force[0] - previous[0]) * (force[0] - previous[0]) +
                                                  (force[1] - previous[1]) * (force[1] - previous[1]) +
                                                  (force[2] - previous[2]) * (force[2] - previous[2]));
                    std::copy(force, force + 3, previous);
                    max_force = std::max(max_force, magnitude);
                    jump_max = std::max(jump_max, jump);
                    jump_sum2 += jump * jump;
                    ++jumps;
                    const std::vector<double> now_axis = sample_axis(scene.get(), samples);
                    const double shaft_top[3] = {tip[0], tip[1], tip[2] + kToolLength};
                    for (uint32_t i = 0; i < samples; ++i) {
                        const double depth = r + kToolRadius - distance_to_segment(&now_axis[3 * i], tip, shaft_top);
                        if (depth > 0) {
                            max_pen = std::max(max_pen, depth);
                            sum_pen2 += depth * depth;
                            ++pen_count;
                        }
                    }
                }
                us = median(times);
                rollbacks = scene_stats(scene.get()).rollbacks;
            } catch (const ApiError& error) {
                status = error.what();
                std::replace(status.begin(), status.end(), ',', ';');
            }
            const double rms_pen = pen_count ? std::sqrt(sum_pen2 / static_cast<double>(pen_count)) : 0.0;
            const double jump_rms = jumps ? std::sqrt(jump_sum2 / static_cast<double>(jumps)) : 0.0;
            progress("tool push spacing %.2f R, stiffness %6.0f N/m: penetration max %.2f mm rms %.2f mm, force max "
                     "%.2f N, step change max %.3f N rms %.4f N, %7.1f us/ms, %.1f s %s",
                     spacing / r, stiffness, 1e3 * max_pen, 1e3 * rms_pen, max_force, jump_max, jump_rms, us,
                     now_s() - start, status.c_str());
            csv.row({num(spacing), num(spacing / r), num(stiffness), num(max_pen), num(rms_pen), num(max_force),
                     num(kToolMaxForce), num(jump_max), num(jump_rms), num(speed * push_s), num(us), num(rollbacks),
                     status});
        }
}

}  // namespace study
