// SPDX-License-Identifier: Apache-2.0
// Collision accuracy: how deep the bowel sinks into the cavity walls and into itself in
// the dense pile, against the collision sphere spacing (R/4 to R) and the contact
// stiffness, with the cost of a 1 ms step.
//
// The pile (study_scenes.h) settles for kSettle, then for kMeasure the study takes a
// snapshot every 50 ms and measures the penetration geometrically on the axis sampled
// every R/8 (so a coarse sphere spacing cannot hide the overlap between its spheres);
// the library's own deepest contact (ent_stats.max_penetration_m, at sphere centres) is
// reported next to it. Cost: median wall time of the steps of the measuring window (in the
// distributed study, those steps again from the window's saved start state, timed alone
// by the serial timing pass).
#include "collision_study.h"

#include "study_runs.h"
#include "study_scenes.h"

#include <algorithm>
#include <cmath>

namespace study {

namespace {

// One pile run's measurements (the error part); us_per_ms is the timing.
struct PileRun {
    Penetration penetration;
    double library_max = 0.0, contacts = 0.0, substeps = std::nan(""), us = std::nan("");
    uint64_t rollbacks = 0;
    std::string status = "ok";
    std::vector<unsigned char> window_state;  // the state the measuring window starts from
};

struct PileTimes {
    double settle_s, measure_s;
    static constexpr double step_s = 1e-3;
    explicit PileTimes(const Options& options)
        : settle_s(options.tiny ? 0.2 : options.fast ? 1.0 : 2.0), measure_s(options.tiny ? 0.1 : options.fast ? 0.5 : 1.0) {}
};

std::string run_name(const PileSettings& settings) {
    return "collision " + exact(settings.sphere_spacing_m) + " " + exact(settings.contact_stiffness_N_per_m);
}

// The settle, then the measuring window with a snapshot every 50 ms; timed: each step of the
// window timed too (the serial study), else the window's start state is kept for the timing pass.
PileRun simulate_pile(const PileSettings& settings, const PileTimes& times, bool timed) {
    PileRun run;
    const double r = kPileRadius;
    const double sample_spacing = r / 8;
    const uint32_t samples = static_cast<uint32_t>(std::lround(6.0 / sample_spacing)) + 1;
    try {
        ScenePtr scene = make_scene(pile_json(settings));
        const long settle_steps = std::lround(times.settle_s / times.step_s);
        const long measure_steps = std::lround(times.measure_s / times.step_s);
        const long snapshot_every = std::lround(0.05 / times.step_s);
        for (long k = 0; k < settle_steps; ++k) check(ent_scene_step(scene.get(), times.step_s), "ent_scene_step");
        if (!timed) run.window_state = save_state(scene.get());
        const ent_stats before = scene_stats(scene.get());
        std::vector<double> step_us;
        long snapshots = 0;
        for (long k = 1; k <= measure_steps; ++k) {
            const double t0 = timed ? now_s() : 0.0;
            check(ent_scene_step(scene.get(), times.step_s), "ent_scene_step");
            if (timed) step_us.push_back((now_s() - t0) * 1e6);
            if (k % snapshot_every == 0) {
                run.penetration.add(measure_pile_penetration(sample_axis(scene.get(), samples), sample_spacing));
                const ent_stats s = scene_stats(scene.get());
                run.library_max = std::max(run.library_max, s.max_penetration_m);
                run.contacts += s.contacts;
                ++snapshots;
            }
        }
        const ent_stats after = scene_stats(scene.get());
        if (timed) run.us = median(step_us);
        run.substeps = static_cast<double>(after.substeps - before.substeps) / static_cast<double>(measure_steps);
        run.rollbacks = after.rollbacks;
        run.contacts /= static_cast<double>(std::max(snapshots, 1L));
    } catch (const ApiError& error) {
        run.status = error.what();
        std::replace(run.status.begin(), run.status.end(), ',', ';');
    }
    return run;
}

// The timing pass: the measuring window's steps again, from its start state, timed alone.
double time_pile_window(const PileSettings& settings, const PileTimes& times, const std::vector<unsigned char>& state) {
    if (state.empty()) return std::nan("");  // the run failed before its window
    std::vector<double> step_us;
    try {
        ScenePtr scene = make_scene(pile_json(settings));
        restore_state(scene.get(), state);
        for (long k = 0; k < std::lround(times.measure_s / times.step_s); ++k) {
            const double t0 = now_s();
            check(ent_scene_step(scene.get(), times.step_s), "ent_scene_step");
            step_us.push_back((now_s() - t0) * 1e6);
        }
    } catch (const ApiError&) {
        return std::nan("");
    }
    return median(step_us);
}

RunRecord to_record(const PileRun& run) {
    RunRecord record;
    record.put("penetration", std::vector<double>{run.penetration.max_m, run.penetration.sum_squares_m2,
                                                  static_cast<double>(run.penetration.penetrating),
                                                  static_cast<double>(run.penetration.samples)});
    record.put("library_max", run.library_max);
    record.put("contacts", run.contacts);
    record.put("substeps", run.substeps);
    record.put("rollbacks", static_cast<double>(run.rollbacks));
    record.put("status", run.status);
    record.put_bytes("window_state", run.window_state);
    return record;
}

PileRun from_record(const RunRecord& record) {
    PileRun run;
    const std::vector<double> p = record.numbers("penetration");
    if (p.size() != 4) throw std::runtime_error("a collision run record without its 4 penetration figures");
    run.penetration.max_m = p[0];
    run.penetration.sum_squares_m2 = p[1];
    run.penetration.penetrating = static_cast<uint64_t>(p[2]);
    run.penetration.samples = static_cast<uint64_t>(p[3]);
    run.library_max = record.number("library_max");
    run.contacts = record.number("contacts");
    run.substeps = record.number("substeps");
    run.rollbacks = static_cast<uint64_t>(record.number("rollbacks"));
    run.status = record.text("status");
    run.window_state = record.bytes("window_state");
    return run;
}

PileSettings settings_of(double spacing, double stiffness) {
    PileSettings settings;
    settings.sphere_spacing_m = spacing;
    settings.contact_stiffness_N_per_m = stiffness;
    return settings;
}

}  // namespace

bool print_collision_run(const Options& options, const std::string& name) {
    const std::vector<std::string> words = name_words(name);
    if (words.size() != 3 || words[0] != "collision") return false;
    const PileSettings settings = settings_of(std::strtod(words[1].c_str(), nullptr), std::strtod(words[2].c_str(), nullptr));
    std::fputs(to_record(simulate_pile(settings, PileTimes(options), false)).serialize().c_str(), stdout);
    return true;
}

void run_collision_study(const Options& options) {
    const double r = kPileRadius;
    const PileTimes times(options);
    Csv csv(csv_path(options, "collision_pile.csv"),
            {"sphere_spacing_m", "sphere_spacing_radii", "contact_stiffness_N_per_m",
             "max_penetration_m", "rms_penetration_m", "max_penetration_radii", "rms_penetration_radii",
             "penetrating_fraction", "library_max_penetration_m", "contacts", "us_per_ms", "substeps_per_ms",
             "rollbacks", "status"});
    for (double spacing : pile_sphere_spacings(options))
        for (double stiffness : pile_contact_stiffnesses(options)) {
            const PileSettings settings = settings_of(spacing, stiffness);
            const double start = now_s();
            PileRun run;
            switch (run_mode(options)) {
                case RunMode::list: list_run(run_name(settings)); continue;
                case RunMode::from_records:
                    run = from_record(load_run(options, run_name(settings)));
                    run.us = time_pile_window(settings, times, run.window_state);
                    break;
                default: run = simulate_pile(settings, times, true);
            }
            const Penetration& penetration = run.penetration;
            progress("collision pile spacing %.2f R, stiffness %6.0f N/m: max %.2f mm, rms %.2f mm, %7.1f us/ms, "
                     "%.1f s %s",
                     spacing / r, stiffness, 1e3 * penetration.max_m, 1e3 * penetration.rms_m(), run.us,
                     now_s() - start, run.status.c_str());
            const double fraction = penetration.samples ? static_cast<double>(penetration.penetrating) /
                                                              static_cast<double>(penetration.samples)
                                                        : std::nan("");
            csv.row({num(spacing), num(spacing / r), num(stiffness), num(penetration.max_m), num(penetration.rms_m()),
                     num(penetration.max_m / r), num(penetration.rms_m() / r), num(fraction), num(run.library_max),
                     num(run.contacts), num(run.us), num(run.substeps), num(run.rollbacks), run.status});
        }
    if (run_mode(options) == RunMode::list) return;  // the rest is timing only: the timing pass runs it
    // Each integrator on the default pile: what its contacts cost. The explicit ones take
    // hundreds of substeps per 1 ms (the contact and self-contact stiffness bound their
    // stable substep), so only the first steps of the drop are timed, for all three alike.
    Csv integrators(csv_path(options, "collision_pile_integrators.csv"),
                    {"integrator", "steps", "us_per_ms", "substeps_per_ms", "status"});
    const int steps = options.fast ? 3 : 10;
    for (int32_t id : kIntegrators) {
        PileSettings settings;
        settings.integrator = integrator_name(id);
        std::vector<double> us;
        std::string status = "ok";
        double substeps = std::nan("");
        try {
            ScenePtr scene = make_scene(pile_json(settings));
            for (int k = 0; k < steps; ++k) {
                const double t0 = now_s();
                check(ent_scene_step(scene.get(), PileTimes::step_s), "ent_scene_step");
                us.push_back((now_s() - t0) * 1e6);
            }
            substeps = static_cast<double>(scene_stats(scene.get()).substeps) / steps;
        } catch (const ApiError& error) {
            status = error.what();
            std::replace(status.begin(), status.end(), ',', ';');
        }
        progress("collision pile %-16s first %d steps: %9.1f us/ms, %.0f substeps/ms %s", settings.integrator, steps,
                 median(us), substeps, status.c_str());
        integrators.row({settings.integrator, num(steps), num(median(us)), num(substeps), status});
    }
}

}  // namespace study
