// SPDX-License-Identifier: Apache-2.0
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
// the collision spheres. Cost: median wall time of the window's steps (in the distributed
// study, those steps again from the first touch's saved state, timed alone by the serial
// timing pass).
#include "tool_push_study.h"

#include "study_runs.h"
#include "study_scenes.h"

#include <algorithm>
#include <cmath>

namespace study {

namespace {

constexpr double kToolRadius = 0.005;   // m
constexpr double kToolLength = 0.3;     // m
constexpr double kToolMaxForce = 8.0;   // N
constexpr double kPushedLength = 1.0;         // m
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
        kPushedLength, kPileRadius, kControlPoints, kPileRadius, spacing, stiffness, kToolRadius, kToolLength,
        kToolMaxForce, 0.5 * kPushedLength, kStartY, 0.5 * kPileRadius);
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

// The motion, its times and the measurements' sampling.
struct Push {
    static constexpr double step_s = 1e-3, settle_s = 0.3;
    static constexpr double press_speed = 0.025, press_s = 0.4, slide_speed = 0.05, slide_s = 0.6, hold_s = 0.1;
    static long press_steps() { return std::lround(press_s / step_s); }
    static long slide_steps() { return std::lround(slide_s / step_s); }
    static long window_steps() { return press_steps() + slide_steps() + std::lround(hold_s / step_s); }
    // Where the tip goes in step k (1, 2, ...) of the window after the first touch.
    static void advance(long k, double tip[3]) {
        if (k <= press_steps()) tip[1] += press_speed * step_s;
        else if (k <= press_steps() + slide_steps()) tip[0] += slide_speed * step_s;
    }
};
const double kIdentity[4] = {1, 0, 0, 0};

// One run's measurements (the error part); us is the timing.
struct ToolRun {
    double max_pen = 0, sum_pen2 = 0, max_force = 0, jump_max = 0, jump_sum2 = 0, us = std::nan("");
    uint64_t pen_count = 0, jumps = 0, rollbacks = 0;
    std::string status = "ok";
    std::vector<unsigned char> touch_state;  // the state at the first touch, where the window starts
    std::vector<double> touch_tip;           // and the tip there
};

std::string tool_push_study_run_name(double spacing, double stiffness) {
    return "tool " + exact(spacing) + " " + exact(stiffness);
}

// timed: each step of the window timed too (the serial study); else the window's start
// (state and tip) is kept for the timing pass.
ToolRun push(double spacing, double stiffness, bool timed) {
    const double r = kPileRadius;
    const double sample_spacing = r / 8;
    const uint32_t samples = static_cast<uint32_t>(std::lround(kPushedLength / sample_spacing)) + 1;
    ToolRun run;
    try {
        ScenePtr scene = make_scene(pressed_bowel_json(spacing, stiffness));
        for (long k = 0; k < std::lround(Push::settle_s / Push::step_s); ++k)
            check(ent_scene_step(scene.get(), Push::step_s), "ent_scene_step");
        double tip[3] = {0.5 * kPushedLength, kStartY, 0.5 * r};
        double force[3] = {0, 0, 0}, torque[3];
        auto step_to = [&](const double* pose) {
            check(ent_tool_set_pose(scene.get(), 0, pose, kIdentity), "ent_tool_set_pose");
            const double t0 = timed ? now_s() : 0.0;
            check(ent_scene_step(scene.get(), Push::step_s), "ent_scene_step");
            const double elapsed = timed ? now_s() - t0 : 0.0;
            check(ent_tool_wrench(scene.get(), 0, force, torque), "ent_tool_wrench");
            return elapsed;
        };
        // Moved sideways until the first touch, at most past the bowel's axis.
        bool touched = false;
        while (!touched && tip[1] < 0.0) {
            tip[1] += Push::press_speed * Push::step_s;
            step_to(tip);
            touched = force[0] != 0.0 || force[1] != 0.0 || force[2] != 0.0;
        }
        if (!touched) throw ApiError("the tool passed the bowel's axis without touching it");
        if (!timed) {
            run.touch_state = save_state(scene.get());
            run.touch_tip.assign(tip, tip + 3);
        }
        double previous[3] = {force[0], force[1], force[2]};
        std::vector<double> times;
        for (long k = 1; k <= Push::window_steps(); ++k) {
            Push::advance(k, tip);
            times.push_back(step_to(tip) * 1e6);
            const double magnitude = std::sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
            const double jump = std::sqrt((force[0] - previous[0]) * (force[0] - previous[0]) +
                                          (force[1] - previous[1]) * (force[1] - previous[1]) +
                                          (force[2] - previous[2]) * (force[2] - previous[2]));
            std::copy(force, force + 3, previous);
            run.max_force = std::max(run.max_force, magnitude);
            run.jump_max = std::max(run.jump_max, jump);
            run.jump_sum2 += jump * jump;
            ++run.jumps;
            const std::vector<double> axis = sample_axis(scene.get(), samples);
            const double shaft_top[3] = {tip[0], tip[1], tip[2] + kToolLength};
            for (uint32_t i = 0; i < samples; ++i) {
                const double depth = r + kToolRadius - distance_to_segment(&axis[3 * i], tip, shaft_top);
                if (depth > 0) {
                    run.max_pen = std::max(run.max_pen, depth);
                    run.sum_pen2 += depth * depth;
                    ++run.pen_count;
                }
            }
        }
        if (timed) run.us = median(times);
        run.rollbacks = scene_stats(scene.get()).rollbacks;
    } catch (const ApiError& error) {
        run.status = error.what();
        std::replace(run.status.begin(), run.status.end(), ',', ';');
    }
    return run;
}

// The timing pass: the window's steps again, from the first touch, timed alone.
double time_push_window(double spacing, double stiffness, const ToolRun& run) {
    if (run.touch_state.empty() || run.touch_tip.size() != 3) return std::nan("");  // no window: the run failed
    std::vector<double> times;
    try {
        ScenePtr scene = make_scene(pressed_bowel_json(spacing, stiffness));
        restore_state(scene.get(), run.touch_state);
        double tip[3] = {run.touch_tip[0], run.touch_tip[1], run.touch_tip[2]};
        for (long k = 1; k <= Push::window_steps(); ++k) {
            Push::advance(k, tip);
            check(ent_tool_set_pose(scene.get(), 0, tip, kIdentity), "ent_tool_set_pose");
            const double t0 = now_s();
            check(ent_scene_step(scene.get(), Push::step_s), "ent_scene_step");
            times.push_back((now_s() - t0) * 1e6);
        }
    } catch (const ApiError&) {
        return std::nan("");
    }
    return median(times);
}

RunRecord tool_push_study_to_record(const ToolRun& run) {
    RunRecord record;
    record.put("penetration", std::vector<double>{run.max_pen, run.sum_pen2, static_cast<double>(run.pen_count)});
    record.put("force", std::vector<double>{run.max_force, run.jump_max, run.jump_sum2, static_cast<double>(run.jumps)});
    record.put("rollbacks", static_cast<double>(run.rollbacks));
    record.put("status", run.status);
    record.put_bytes("touch_state", run.touch_state);
    record.put("touch_tip", run.touch_tip);
    return record;
}

ToolRun tool_run_from(const RunRecord& record) {
    ToolRun run;
    const std::vector<double> penetration = record.numbers("penetration"), force = record.numbers("force");
    if (penetration.size() != 3 || force.size() != 4) throw std::runtime_error("a tool run record with missing figures");
    run.max_pen = penetration[0];
    run.sum_pen2 = penetration[1];
    run.pen_count = static_cast<uint64_t>(penetration[2]);
    run.max_force = force[0];
    run.jump_max = force[1];
    run.jump_sum2 = force[2];
    run.jumps = static_cast<uint64_t>(force[3]);
    run.rollbacks = static_cast<uint64_t>(record.number("rollbacks"));
    run.status = record.text("status");
    run.touch_state = record.bytes("touch_state");
    run.touch_tip = record.numbers("touch_tip");
    return run;
}

}  // namespace

bool print_tool_run(const Options&, const std::string& name) {
    const std::vector<std::string> words = name_words(name);
    if (words.size() != 3 || words[0] != "tool") return false;
    const ToolRun run = push(std::strtod(words[1].c_str(), nullptr), std::strtod(words[2].c_str(), nullptr), false);
    std::fputs(tool_push_study_to_record(run).serialize().c_str(), stdout);
    return true;
}

void run_tool_push_study(const Options& options) {
    Csv csv(csv_path(options, "collision_tool.csv"),
            {"sphere_spacing_m", "sphere_spacing_radii", "contact_stiffness_N_per_m", "max_penetration_m",
             "rms_penetration_m", "max_force_N", "tool_max_force_N", "force_jump_max_N", "force_jump_rms_N",
             "us_per_ms", "rollbacks", "status"});
    for (double spacing : pile_sphere_spacings(options))
        for (double stiffness : pile_contact_stiffnesses(options)) {
            const double start = now_s();
            ToolRun run;
            switch (run_mode(options)) {
                case RunMode::list: list_run(tool_push_study_run_name(spacing, stiffness)); continue;
                case RunMode::from_records:
                    run = tool_run_from(load_run(options, tool_push_study_run_name(spacing, stiffness)));
                    run.us = time_push_window(spacing, stiffness, run);
                    break;
                default: run = push(spacing, stiffness, true);
            }
            const double rms_pen = run.pen_count ? std::sqrt(run.sum_pen2 / static_cast<double>(run.pen_count)) : 0.0;
            const double jump_rms = run.jumps ? std::sqrt(run.jump_sum2 / static_cast<double>(run.jumps)) : 0.0;
            progress("tool spacing %.2f R, stiffness %6.0f N/m: penetration max %.2f mm rms %.2f mm, force max "
                     "%.2f N, step change max %.3f N rms %.4f N, %6.1f us/ms, %.1f s %s",
                     spacing / kPileRadius, stiffness, 1e3 * run.max_pen, 1e3 * rms_pen, run.max_force, run.jump_max,
                     jump_rms, run.us, now_s() - start, run.status.c_str());
            csv.row({num(spacing), num(spacing / kPileRadius), num(stiffness), num(run.max_pen), num(rms_pen),
                     num(run.max_force), num(kToolMaxForce), num(run.jump_max), num(jump_rms), num(run.us),
                     num(run.rollbacks), run.status});
        }
}

}  // namespace study
