// Collision accuracy at the tool: a grasper presses a bowel lying on the floor and slides
// along it, against the collision sphere spacing and the contact stiffness.
// The tool is a direct capsule (JSON "mode": "direct"): the bowel meets it where it is put,
// so the penetration measures the contact law. A proxy tool (the default, docs/haptics.md)
// stands off by its coupling spring's stretch, whatever the contact stiffness.
//
// The scene is deterministic (a pile is not: each knob would give another pile): a 1 m
// bowel (41 control points, the 2.5 cm segments of the 6 m default), straight along x on a
// floor plane, gravity, damping, the pile's contact law, and one vertical tool (JSON
// "tools": radius 5 mm, 30 cm shaft, 8 N bound) standing on the floor beside the bowel's
// middle, 5 mm from its surface. After 0.3 s at rest the tool moves sideways (+y) at
// 2.5 cm/s until it first feels a force, then 1 cm further, pushing the bowel across the
// floor (0.4 s), then slides along the bowel (+x) at 5 cm/s for 0.6 s (3 cm, over several
// sphere spacings) while pressing, then holds for 0.1 s; one ent_tool_set_pose per 1 ms
// step. From the first touch on, every step: the penetration of the tube into the tool
// capsule (R + tool radius - distance from the axis, sampled every R/8, to the shaft
// segment) and the force on the tool (ent_tool_wrench). Reported: max and RMS
// penetration, the largest force, and the step-to-step change of the force
// |F(k) - F(k-1)| (max and RMS): what a haptic device feels as roughness while sliding over
// the collision spheres.
#include "tool_push_study.h"

#include "study_scenes.h"

#include <algorithm>
#include <cmath>

namespace study {

namespace {

constexpr double kToolRadius = 0.005;   // m
constexpr double kToolLength = 0.3;     // m
constexpr double kToolMaxForce = 8.0;   // N
constexpr double kLength = 1.0;         // m
constexpr uint32_t kControlPoints = 41;
// The tool starts beside the bowel's middle, 5 mm from its surface, its tip R/2 above the
// floor, so that its shaft meets the tube's side at the axis's height.
constexpr double kStartY = -(0.0125 + kToolRadius + 0.005);

std::string pressed_bowel_json(double spacing, double stiffness) {
    return format(
        "{\"intestine\": {\"length\": %.17g, \"radius\": %.17g, \"control_points\": %u,"
        " \"linear_density\": 0.3, \"stretch_stiffness\": 100, \"bend_stiffness\": 0.0025,"
        " \"shape\": {\"kind\": \"line\", \"center\": [0, 0, %.17g], \"direction\": [1, 0, 0]}},"
        " \"solver\": {\"integrator\": \"implicit_euler\", \"timestep\": 0.001},"
        " \"gravity\": [0, 0, -9.81], \"damping\": {},"
        " \"collision\": {\"sphere_spacing\": %.17g, \"stiffness\": %.17g},"
        " \"environment\": [{\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 0, 1]}],"
        " \"tools\": [{\"mode\": \"direct\", \"radius\": %.17g, \"length\": %.17g, \"max_force\": %.17g,"
        " \"position\": [%.17g, %.17g, %.17g], \"orientation\": [1, 0, 0, 0]}]}",
        kLength, kPileRadius, kControlPoints, kPileRadius, spacing, stiffness, kToolRadius, kToolLength,
        kToolMaxForce, 0.5 * kLength, kStartY, 0.5 * kPileRadius);
}

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
    const double step_s = 1e-3, settle_s = 0.3;
    const double press_speed = 0.025, press_s = 0.4, slide_speed = 0.05, slide_s = 0.6, hold_s = 0.1;
    const double sample_spacing = r / 8;
    const uint32_t samples = static_cast<uint32_t>(std::lround(kLength / sample_spacing)) + 1;
    const double identity[4] = {1, 0, 0, 0};

    Csv csv(options.out_dir + "/collision_tool.csv",
            {"sphere_spacing_m", "sphere_spacing_radii", "contact_stiffness_N_per_m", "max_penetration_m",
             "rms_penetration_m", "max_force_N", "tool_max_force_N", "force_jump_max_N", "force_jump_rms_N",
             "us_per_ms", "rollbacks", "status"});
    for (double spacing : spacings)
        for (double stiffness : stiffnesses) {
            double max_pen = 0, sum_pen2 = 0, max_force = 0, jump_max = 0, jump_sum2 = 0, us = std::nan("");
            uint64_t pen_count = 0, jumps = 0, rollbacks = 0;
            std::string status = "ok";
            const double start = now_s();
            try {
                ScenePtr scene = make_scene(pressed_bowel_json(spacing, stiffness));
                for (long k = 0; k < std::lround(settle_s / step_s); ++k)
                    check(ent_scene_step(scene.get(), step_s), "ent_scene_step");
                double tip[3] = {0.5 * kLength, kStartY, 0.5 * r};
                double force[3] = {0, 0, 0}, torque[3];
                auto step_to = [&](const double* pose) {
                    check(ent_tool_set_pose(scene.get(), 0, pose, identity), "ent_tool_set_pose");
                    const double t0 = now_s();
                    check(ent_scene_step(scene.get(), step_s), "ent_scene_step");
                    const double elapsed = now_s() - t0;
                    check(ent_tool_wrench(scene.get(), 0, force, torque), "ent_tool_wrench");
                    return elapsed;
                };
                // Moved sideways until the first touch, at most past the bowel's axis.
                bool touched = false;
                while (!touched && tip[1] < 0.0) {
                    tip[1] += press_speed * step_s;
                    step_to(tip);
                    touched = force[0] != 0.0 || force[1] != 0.0 || force[2] != 0.0;
                }
                if (!touched) throw ApiError("the tool passed the bowel's axis without touching it");
                double previous[3] = {force[0], force[1], force[2]};
                std::vector<double> times;
                const long press = std::lround(press_s / step_s), slide = std::lround(slide_s / step_s);
                const long steps = press + slide + std::lround(hold_s / step_s);
                for (long k = 1; k <= steps; ++k) {
                    if (k <= press) tip[1] += press_speed * step_s;
                    else if (k <= press + slide) tip[0] += slide_speed * step_s;
                    times.push_back(step_to(tip) * 1e6);
                    const double magnitude = std::sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
                    const double jump = std::sqrt((force[0] - previous[0]) * (force[0] - previous[0]) +
                                                  (force[1] - previous[1]) * (force[1] - previous[1]) +
                                                  (force[2] - previous[2]) * (force[2] - previous[2]));
                    std::copy(force, force + 3, previous);
                    max_force = std::max(max_force, magnitude);
                    jump_max = std::max(jump_max, jump);
                    jump_sum2 += jump * jump;
                    ++jumps;
                    const std::vector<double> axis = sample_axis(scene.get(), samples);
                    const double shaft_top[3] = {tip[0], tip[1], tip[2] + kToolLength};
                    for (uint32_t i = 0; i < samples; ++i) {
                        const double depth = r + kToolRadius - distance_to_segment(&axis[3 * i], tip, shaft_top);
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
            progress("tool spacing %.2f R, stiffness %6.0f N/m: penetration max %.2f mm rms %.2f mm, force max "
                     "%.2f N, step change max %.3f N rms %.4f N, %6.1f us/ms, %.1f s %s",
                     spacing / r, stiffness, 1e3 * max_pen, 1e3 * rms_pen, max_force, jump_max, jump_rms, us,
                     now_s() - start, status.c_str());
            csv.row({num(spacing), num(spacing / r), num(stiffness), num(max_pen), num(rms_pen), num(max_force),
                     num(kToolMaxForce), num(jump_max), num(jump_rms), num(us), num(rollbacks), status});
        }
}

}  // namespace study
