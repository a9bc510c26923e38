// SPDX-License-Identifier: Apache-2.0
// Peers on the swing: MuJoCo's composite rope (bench/peers/mujoco_rope.h) on the mechanics
// study's swinging scene (mechanics_scenes.h): the same length, radius, mass per length,
// bending and stretch stiffness, stretch damping, drag, gravity, pinned first end, straight
// horizontal start at rest, and the same N, time steps and times as our settings.
//
// Two ropes:
//   mujoco_rope        as close as MuJoCo 2.2.2 allows: hinge springs EI / l, stretch
//                      joints EA / l with damping c / l, drag -c v per metre (through
//                      MuJoCo's passive-force callback), the first end held by a ball joint;
//   mujoco_rope_rigid  the same with rigid segments (the collision benchmark's rope), to
//                      show what leaving stretching out costs: our EA = 100 N lets the
//                      swinging bowel lengthen by several per cent (8 % at 2 s).
// Both use MuJoCo's default integrator, Euler (semi-implicit; joint damping implicit).
// Settings: the mechanics N sweep at 1 ms (the rigid rope up to the N of the time-step
// sweep); its time-step sweep at its N (mujoco_rope); in full mode also the time steps down
// to 5e-5 s at N = 60, where MuJoCo is cheap enough to show its own convergence in time.
// Cost: median wall time of one mj_step, scaled to 1 ms simulated (x 1 ms / dt), like
// ours. MuJoCo works in joint coordinates, where the mass matrix of a chain is dense: its
// step grows like N^3 (ours like N). So a setting whose whole run is projected beyond the
// budget is timed on a few steps only ("timed only": cost and finiteness, no error), and
// one whose model build and first steps are projected beyond it is not run.
#include "peers_study.h"

#include "mechanics_scenes.h"
#include "peers/mujoco_rope.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace study {

namespace {

using enteron::peers::MujocoIntegrator;
using enteron::peers::MujocoRope;
using enteron::peers::MujocoRopeDesc;

constexpr uint32_t kTimeConvergencePoints = 60;      // full mode: MuJoCo's own time convergence
constexpr double kTimeConvergenceSmallestStep = 5e-5;
constexpr uint64_t kMinTimedSteps = 5;

struct Budget {
    double run_s;     // wall time allowed for one setting's whole run
    double timing_s;  // wall time of the steps timed when the run would exceed it
};

struct Setting {
    bool stretch;
    uint32_t control_points;
    double timestep;
    bool operator<(const Setting& o) const {
        return std::tie(stretch, control_points, timestep) < std::tie(o.stretch, o.control_points, o.timestep);
    }
};

struct Run {
    std::vector<std::vector<double>> axes;  // one per time reached
    double us_per_ms = std::nan("");
    bool finite = true;
    uint64_t steps = 0;
    double build_s = std::nan("");
    double wall_s = 0.0;
    std::string status = "ok";
};

const char* peer_name(bool stretch) { return stretch ? "mujoco_rope" : "mujoco_rope_rigid"; }

MujocoRopeDesc rope_desc(const Setting& setting) {
    const MechanicsBowel& b = kMechanicsBowel;
    MujocoRopeDesc desc;
    desc.length_m = b.length_m;
    desc.radius_m = b.radius_m;
    desc.points = setting.control_points;
    desc.linear_density_kg_per_m = b.linear_density_kg_per_m;
    desc.bend_stiffness_N_m2 = b.bend_stiffness_N_m2;
    const double l = b.length_m / (setting.control_points - 1);
    desc.joint_damping_N_m_s = b.bend_damping_N_m2_s / l;  // bending moment per curvature rate, curvature ~ angle / l
    if (setting.stretch) {
        desc.stretch_stiffness_N = b.stretch_stiffness_N;
        desc.stretch_damping_N_s = b.stretch_damping_N_s;
    }
    desc.drag_N_s_per_m2 = b.drag_N_s_per_m2;
    desc.timestep_s = setting.timestep;
    desc.integrator = MujocoIntegrator::euler;
    desc.gravity_m_per_s2[0] = desc.gravity_m_per_s2[1] = 0.0;
    desc.gravity_m_per_s2[2] = -b.gravity_m_per_s2;
    desc.self_collision = false;  // the swing names no collision
    desc.pin_first = true;
    desc.max_contacts = 1;        // nothing to touch
    desc.max_constraint_rows = 4;
    const double start[3] = {0.0, 0.0, 0.0}, direction[3] = {1.0, 0.0, 0.0};  // as mechanics_scene_json
    desc.initial_points_xyz_m =
        enteron::peers::line_points(setting.control_points, b.length_m, start, direction);
    return desc;
}

std::string axis_text(const std::vector<double>& axis) {
    std::string text;
    for (std::size_t i = 0; i < axis.size(); ++i) text += (i ? " " : "") + format("%.9g", axis[i]);
    return text;
}

class PeersStudy {
public:
    explicit PeersStudy(const Options& options)
        : options_(options),
          grid_(mechanics_grid(options)),
          budget_(options.fast ? Budget{3.0, 0.3} : Budget{300.0, 3.0}) {}

    void run() {
        Csv csv(options_.out_dir + "/peers.csv",
                {"peer", "scene", "sweep", "integrator", "control_points", "timestep_s", "t_s", "us_per_ms", "finite",
                 "steps_timed", "build_s", "status", "axis_xyz_m"});
        for (uint32_t n : grid_.sizes) emit(csv, "N", {true, n, kOneMs});
        for (uint32_t n : grid_.sizes)  // for scale only: up to the N of the time-step sweep
            if (n <= grid_.dt_sweep_points) emit(csv, "N", {false, n, kOneMs});
        for (double h : grid_.timesteps_s) emit(csv, "dt", {true, grid_.dt_sweep_points, h});
        if (grid_.dt_sweep_points != kTimeConvergencePoints)
            for (double h : grid_.timesteps_s)
                if (h >= kTimeConvergenceSmallestStep) emit(csv, "dt_own", {true, kTimeConvergencePoints, h});
    }

private:
    void emit(Csv& csv, const char* sweep, const Setting& setting) {
        const Run& run = get(setting);
        for (std::size_t k = 0; k < grid_.times_s.size(); ++k)
            csv.row({peer_name(setting.stretch), "swing", sweep,
                     enteron::peers::mujoco_integrator_name(MujocoIntegrator::euler), num(setting.control_points),
                     num(setting.timestep), num(grid_.times_s[k]), num(run.us_per_ms), num(run.finite ? 1 : 0),
                     num(run.steps), num(run.build_s), run.status,
                     k < run.axes.size() ? axis_text(run.axes[k]) : std::string()});
    }

    const Run& get(const Setting& setting) {
        auto found = cache_.find(setting);
        if (found != cache_.end()) return found->second;
        Run run = simulate(setting);
        progress("peers %-17s N=%-4u dt=%-7g %10.1f us/ms  build %6.2f s  %6.1f s  %s", peer_name(setting.stretch),
                 setting.control_points, setting.timestep, run.us_per_ms, run.build_s, run.wall_s,
                 run.status.c_str());
        return cache_.emplace(setting, std::move(run)).first->second;
    }

    // What the last rope of the same kind cost, scaled by N^3 (the dense chain).
    struct Projection {
        double build_s = 0.0;
        double step_us = 0.0;
    };
    Projection project(const Setting& setting) const {
        Projection p;
        for (const auto& [other, run] : cache_) {
            if (other.stretch != setting.stretch || other.control_points >= setting.control_points ||
                !(run.us_per_ms > 0.0))
                continue;
            const double scale = std::pow(double(setting.control_points) / other.control_points, 3);
            p.build_s = std::max(p.build_s, run.build_s * scale);
            p.step_us = std::max(p.step_us, run.us_per_ms * other.timestep / kOneMs * scale);
        }
        return p;
    }

    Run simulate(const Setting& setting) const {
        Run run;
        const double start = now_s();
        const Projection projected = project(setting);
        const double first_steps_s = projected.build_s + kMinTimedSteps * projected.step_us * 1e-6;
        if (first_steps_s > budget_.run_s) {
            run.status = format("not run: model build and %llu steps projected at %.0f s (N^3)",
                                static_cast<unsigned long long>(kMinTimedSteps), first_steps_s);
            return run;
        }
        std::string error;
        auto rope = MujocoRope::create(rope_desc(setting), &error);
        run.build_s = now_s() - start;
        if (!rope) {
            run.status = "build failed: " + error;
            std::replace(run.status.begin(), run.status.end(), ',', ';');
            return run;
        }
        const double h = setting.timestep;
        const double total_steps = std::round(grid_.times_s.back() / h);
        std::vector<double> samples;
        double timed_us = 0.0;
        bool timed_only = false, stop = false;
        for (double t : grid_.times_s) {
            while (!stop && rope->time_s() < t - 0.5 * h) {
                const double simulated = rope->time_s();  // MuJoCo resets its state (and time) on a bad acceleration
                const double t0 = now_s();
                const bool ok = rope->step();
                const double us = (now_s() - t0) * 1e6;
                samples.push_back(us);
                timed_us += us;
                if (!ok) {
                    run.finite = false;
                    run.status = format("not finite in the step from t = %.4g s", simulated);
                    stop = true;
                } else if (!timed_only && (samples.size() == kMinTimedSteps || samples.size() % 200 == 0)) {
                    const double remaining = total_steps - static_cast<double>(samples.size());
                    const double projected_s = (now_s() - start) + remaining * median(samples) * 1e-6;
                    if (projected_s > budget_.run_s) {
                        timed_only = true;
                        run.status = format("timed only: the run to t = %g s would take about %.0f s",
                                            grid_.times_s.back(), projected_s);
                    }
                }
                if (timed_only && samples.size() >= kMinTimedSteps && timed_us >= budget_.timing_s * 1e6) stop = true;
            }
            if (stop) break;
            run.axes.emplace_back();
            rope->axis(kAxisSamples, run.axes.back());
        }
        run.steps = samples.size();
        run.us_per_ms = median(samples) * kOneMs / h;
        run.wall_s = now_s() - start;
        return run;
    }

    const Options& options_;
    MechanicsGrid grid_;
    Budget budget_;
    std::map<Setting, Run> cache_;
};

}  // namespace

std::string peers_in_this_build() { return enteron::peers::mujoco_version(); }

void run_peers_study(const Options& options) { PeersStudy(options).run(); }

}  // namespace study
