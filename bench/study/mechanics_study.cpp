// SPDX-License-Identifier: Apache-2.0
// Mechanics accuracy: the error of the axis against a converged reference, for each knob
// (control points N, integrator, time step), with the cost of a 1 kHz step.
//
// Scenes (deterministic, not chaotic; mechanics_scenes.h): a bowel of length L = 6 m,
// R = 12.5 mm, 0.3 kg/m, EA = 100 N, EI = 2.5e-3 N m^2, gravity, drag 1 N s/m^2:
//   swing  pinned at its first end, released from horizontal, swinging down;
//   sag    pinned at both ends, straight and horizontal at first, sagging under gravity
//          to rest;
//   drop   the swing with a floor 0.5 m below the pin: the bowel drops onto the plane.
// Error: RMS distance between the axis and the reference's, both sampled at kSamples
// points evenly spaced in arc length (ent_scene_axis), at each time of the grid.
// Cost: median wall time of one ent_scene_step, scaled to 1 ms of simulated time (what a
// 1 kHz loop pays); a time step above 1 ms is stepped as one call of that length. Measured
// over the whole run; in the distributed study (study_runs.h) over its first
// --timing-steps steps, by the serial timing pass.
// The explicit integrators never take a substep above their stability limit, whatever
// the time step asked: the effective substep (simulated time / substeps) is reported.
#include "mechanics_study.h"

#include "mechanics_scenes.h"
#include "study_runs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace study {

namespace {

using Scene = MechanicsScene;
const char* scene_name(Scene scene) { return mechanics_scene_name(scene); }
constexpr double kLength = kMechanicsBowel.length_m;
constexpr uint32_t kSamples = kAxisSamples;

struct Setting {
    Scene scene;
    uint32_t control_points;
    int32_t integrator;
    double timestep;
    bool operator<(const Setting& o) const {
        return std::tie(scene, control_points, integrator, timestep) <
               std::tie(o.scene, o.control_points, o.integrator, o.timestep);
    }
};

struct Run {
    std::vector<std::vector<double>> axes;  // one per time of the study; empty on failure
    double us_per_ms = std::nan("");        // median wall time per 1 ms simulated
    double substep_s = std::nan("");        // effective substep
    uint64_t rollbacks = 0;
    std::string status = "ok";
    double wall_s = 0.0;
};

class MechanicsStudy {
public:
    MechanicsStudy(const Options& options) : options_(options) {
        const MechanicsGrid grid = mechanics_grid(options);
        times_ = grid.times_s;
        sizes_ = grid.sizes;
        reference_ = {grid.reference_points, grid.reference_integrator, grid.reference_timestep_s};
        dt_sweep_points_ = grid.dt_sweep_points;
        timesteps_ = grid.timesteps_s;
        scenes_ = grid.scenes;
    }

    void run() {
        Csv reference_csv(csv_path(options_, "mechanics_reference.csv"),
                          {"scene", "t_s", "reference", "compared_with", "difference_m", "difference_rel",
                           "reference_wall_s"});
        // The reference axes themselves, so that a peer (bench/peers) can be measured against them.
        Csv axes_csv(csv_path(options_, "mechanics_reference_axes.csv"), {"scene", "t_s", "index", "x_m", "y_m", "z_m"});
        Csv csv(csv_path(options_, "mechanics.csv"),
                {"scene", "sweep", "integrator", "control_points", "timestep_s", "substep_s", "t_s", "error_m",
                 "error_rel", "time_error_m", "next_difference_m", "us_per_ms", "rollbacks", "at_reference_N", "status"});
        for (Scene scene : scenes_) {
            const Setting ref{scene, reference_.points, reference_.integrator, reference_.timestep};
            const Run& reference = get(ref);
            if (reference.axes.empty())
                throw std::runtime_error(format("the %s reference failed: %s", scene_name(scene),
                                                reference.status.c_str()));
            for (std::size_t k = 0; k < times_.size(); ++k)
                for (std::size_t i = 0; i < kSamples; ++i)
                    axes_csv.row({scene_name(scene), num(times_[k]), num(static_cast<uint64_t>(i)),
                                  format("%.9g", reference.axes[k][3 * i]), format("%.9g", reference.axes[k][3 * i + 1]),
                                  format("%.9g", reference.axes[k][3 * i + 2])});
            // Self-convergence of the reference: half the control points; half the time step.
            const Setting half_n{scene, reference_.points / 2, reference_.integrator, reference_.timestep};
            const Setting half_dt{scene, reference_.points, reference_.integrator, 0.5 * reference_.timestep};
            for (const auto& [label, setting] : {std::pair{"half_N", half_n}, std::pair{"half_dt", half_dt}}) {
                const Run& other = get(setting);
                for (std::size_t k = 0; k < times_.size(); ++k) {
                    const double d = other.axes.empty() ? std::nan("") : rms_distance(other.axes[k], reference.axes[k]);
                    reference_csv.row({scene_name(scene), num(times_[k]), describe(ref), label, num(d),
                                       num(d / kLength), num(reference.wall_s)});
                }
            }

            // N sweep: every integrator at the 1 ms step of a 1 kHz loop, and rk4 at the
            // reference's time step (the spatial error alone).
            // next_difference_m: the distance to the same setting with 2N, which gives the
            // observed order without trusting the reference.
            for (uint32_t n : sizes_) {
                for (int32_t integrator : kIntegrators)
                    emit(csv, "N", {scene, n, integrator, kOneMs}, reference, nullptr, nullptr);
                if (n == reference_.points) continue;
                const Run& doubled = get({scene, 2 * n, reference_.integrator, reference_.timestep});
                emit(csv, "N_fine_dt", {scene, n, reference_.integrator, reference_.timestep}, reference, nullptr,
                     &doubled);
            }
            // Time-step sweep at one N; the time error is measured against rk4 at the
            // reference's time step with the same N (the spatial error taken out).
            const Setting same_n{scene, dt_sweep_points_, reference_.integrator, reference_.timestep};
            const Run& temporal = get(same_n);
            for (int32_t integrator : kIntegrators)
                for (double h : timesteps_)
                    emit(csv, "dt", {scene, dt_sweep_points_, integrator, h}, reference, &temporal, nullptr);
        }
    }

    static std::string run_name(const Setting& s) {
        return format("mechanics %s %s %u %s", scene_name(s.scene), integrator_name(s.integrator), s.control_points,
                      exact(s.timestep).c_str());
    }

    // --run NAME: false if NAME is not a mechanics run.
    bool print_record(const std::string& name) {
        Setting setting{};
        if (!parse_run_name(name, setting)) return false;
        const Run run = simulate(setting, false);
        RunRecord record;
        std::vector<double> axes;
        for (const std::vector<double>& axis : run.axes) axes.insert(axes.end(), axis.begin(), axis.end());
        record.put("axes", axes);
        record.put("substep_s", run.substep_s);
        record.put("rollbacks", static_cast<double>(run.rollbacks));
        record.put("status", run.status);
        record.put("wall_s", run.wall_s);
        std::fputs(record.serialize().c_str(), stdout);
        return true;
    }

private:
    struct ReferenceSetting {
        uint32_t points;
        int32_t integrator;
        double timestep;
    };

    static std::string describe(const Setting& s) {
        return format("%s N=%u dt=%g", integrator_name(s.integrator), s.control_points, s.timestep);
    }

    void emit(Csv& csv, const char* sweep, const Setting& setting, const Run& reference, const Run* temporal,
              const Run* next) {
        const Run& run = get(setting);
        for (std::size_t k = 0; k < times_.size(); ++k) {
            const bool ok = !run.axes.empty();
            const double error = ok ? rms_distance(run.axes[k], reference.axes[k]) : std::nan("");
            const double time_error =
                ok && temporal != nullptr && !temporal->axes.empty() ? rms_distance(run.axes[k], temporal->axes[k])
                                                                     : std::nan("");
            const double next_difference =
                ok && next != nullptr && !next->axes.empty() ? rms_distance(run.axes[k], next->axes[k]) : std::nan("");
            csv.row({scene_name(setting.scene), sweep, integrator_name(setting.integrator), num(setting.control_points),
                     num(setting.timestep), num(run.substep_s), num(times_[k]), num(error), num(error / kLength),
                     num(time_error), num(next_difference), num(run.us_per_ms), num(run.rollbacks),
                     num(setting.control_points == reference_.points ? 1 : 0), run.status});
        }
    }

    const Run& get(const Setting& setting) {
        auto found = cache_.find(setting);
        if (found != cache_.end()) return found->second;
        Run run;
        switch (run_mode(options_)) {
            case RunMode::list:  // a run of zeros: enough for run() to name every run it needs
                list_run(run_name(setting));
                run.axes.assign(times_.size(), std::vector<double>(3 * kSamples, 0.0));
                return cache_.emplace(setting, std::move(run)).first->second;
            case RunMode::from_records:
                run = from_record(load_run(options_, run_name(setting)));
                run.us_per_ms = time_first_steps(setting);
                break;
            default:
                run = simulate(setting, true);
        }
        progress("mechanics %-5s %-16s N=%-4u dt=%-7g substep=%-9.3g %8.1f us/ms  %6.1f s  %s", scene_name(setting.scene),
                 integrator_name(setting.integrator), setting.control_points, setting.timestep, run.substep_s,
                 run.us_per_ms, run.wall_s, run.status.c_str());
        return cache_.emplace(setting, std::move(run)).first->second;
    }

    static bool parse_run_name(const std::string& name, Setting& out) {
        const std::vector<std::string> words = name_words(name);
        if (words.size() != 5 || words[0] != "mechanics") return false;
        bool scene_found = false, integrator_found = false;
        for (MechanicsScene scene : {MechanicsScene::swing, MechanicsScene::sag, MechanicsScene::drop})
            if (words[1] == mechanics_scene_name(scene)) out.scene = scene, scene_found = true;
        for (int32_t integrator : kIntegrators)
            if (words[2] == integrator_name(integrator)) out.integrator = integrator, integrator_found = true;
        out.control_points = static_cast<uint32_t>(std::strtoul(words[3].c_str(), nullptr, 10));
        out.timestep = std::strtod(words[4].c_str(), nullptr);
        if (!scene_found || !integrator_found || out.control_points == 0 || !(out.timestep > 0))
            throw std::runtime_error("not a mechanics run: \"" + name + "\"");
        return true;
    }

    Run from_record(const RunRecord& record) const {
        Run run;
        run.status = record.text("status");
        run.substep_s = record.number("substep_s");
        run.rollbacks = static_cast<uint64_t>(record.number("rollbacks"));
        run.wall_s = record.number("wall_s");
        const std::vector<double> axes = record.numbers("axes");
        const std::size_t size = 3 * static_cast<std::size_t>(kSamples);
        if (axes.size() % size != 0 || (!axes.empty() && axes.size() != size * times_.size()))
            throw std::runtime_error("a mechanics run record with " + std::to_string(axes.size()) + " axis values");
        for (std::size_t k = 0; k * size < axes.size(); ++k)
            run.axes.emplace_back(axes.begin() + static_cast<long>(k * size), axes.begin() + static_cast<long>((k + 1) * size));
        return run;
    }

    // The timing pass: the median cost of the first --timing-steps outer steps (all of them
    // when the run has fewer), from the scene's start.
    double time_first_steps(const Setting& setting) const {
        const double outer = std::max(setting.timestep, kOneMs);
        const long steps = std::min(options_.timing_steps, std::lround(times_.back() / outer));
        std::vector<double> samples;
        try {
            ScenePtr scene = make_scene(mechanics_scene_json(setting.scene, setting.control_points, setting.integrator,
                                                             setting.timestep));
            for (long k = 0; k < steps; ++k) {
                const double t0 = now_s();
                check(ent_scene_step(scene.get(), outer), "ent_scene_step");
                samples.push_back((now_s() - t0) * 1e6 * kOneMs / outer);
            }
        } catch (const ApiError&) {
            return std::nan("");  // the run failed too: its status says why
        }
        return median(samples);
    }

    // timed: the cost of every step measured too (the serial study); otherwise the error
    // part only (--run), and us_per_ms stays NaN.
    Run simulate(const Setting& setting, bool timed) const {
        Run run;
        const double start = now_s();
        const double outer = std::max(setting.timestep, kOneMs);
        try {
            ScenePtr scene = make_scene(mechanics_scene_json(setting.scene, setting.control_points, setting.integrator,
                                                   setting.timestep));
            std::vector<double> samples;
            long done = 0;
            for (double t : times_) {
                const long target = std::lround(t / outer);
                for (; done < target; ++done) {
                    const double t0 = timed ? now_s() : 0.0;
                    check(ent_scene_step(scene.get(), outer), "ent_scene_step");
                    if (timed) samples.push_back((now_s() - t0) * 1e6 * kOneMs / outer);
                }
                run.axes.push_back(sample_axis(scene.get(), kSamples));
            }
            const ent_stats stats = scene_stats(scene.get());
            if (timed) run.us_per_ms = median(samples);
            run.substep_s = stats.time_s / static_cast<double>(stats.substeps);
            run.rollbacks = stats.rollbacks;
        } catch (const ApiError& error) {
            run.axes.clear();
            run.status = error.what();
            std::replace(run.status.begin(), run.status.end(), ',', ';');
        }
        run.wall_s = now_s() - start;
        return run;
    }

    const Options& options_;
    std::vector<double> times_;
    std::vector<uint32_t> sizes_;
    ReferenceSetting reference_{};
    uint32_t dt_sweep_points_ = 0;
    std::vector<double> timesteps_;
    std::vector<Scene> scenes_;
    std::map<Setting, Run> cache_;
};

}  // namespace

void run_mechanics_study(const Options& options) { MechanicsStudy(options).run(); }

bool print_mechanics_run(const Options& options, const std::string& name) {
    return MechanicsStudy(options).print_record(name);
}

}  // namespace study
