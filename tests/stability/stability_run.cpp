// SPDX-License-Identifier: Apache-2.0
#include "stability_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

namespace stability {

namespace {

constexpr uint32_t kAxisSamples = 64;

struct SceneDeleter {
    void operator()(ent_scene* scene) const { ent_scene_destroy(scene); }
};

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

std::string call_failure(const char* call, ent_status status) {
    return std::string(call) + " failed: " + ent_status_string(status) + ": " + ent_last_error();
}

// The first non-finite value of `values`, or -1.
long first_non_finite(const std::vector<double>& values) {
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i])) return static_cast<long>(i);
    return -1;
}

class Checker {
public:
    explicit Checker(ent_scene* scene) : scene_(scene), axis_(3 * kAxisSamples) {
        stats_.struct_size = sizeof stats_;
    }

    // Reads the published state; false (with `failure`) if a call fails or a value is not finite.
    bool read(std::string& failure) {
        ent_status status = ent_scene_stats(scene_, &stats_);
        if (status != ENT_OK) return (failure = call_failure("ent_scene_stats", status)), false;
        uint32_t count = 0;
        points_.resize(3 * std::size_t{stats_.control_points});
        status = ent_scene_control_points(scene_, stats_.control_points, points_.data(), &count);
        if (status != ENT_OK) return (failure = call_failure("ent_scene_control_points", status)), false;
        status = ent_scene_axis(scene_, kAxisSamples, axis_.data());
        if (status != ENT_OK) return (failure = call_failure("ent_scene_axis", status)), false;
        if (long i = first_non_finite(points_); i >= 0)
            return (failure = "control point coordinate " + std::to_string(i) + " is not finite"), false;
        if (long i = first_non_finite(axis_); i >= 0)
            return (failure = "axis sample coordinate " + std::to_string(i) + " is not finite"), false;
        const double values[] = {stats_.time_s, stats_.kinetic_energy_J, stats_.potential_energy_J,
                                 stats_.max_penetration_m};
        for (double v : values)
            if (!std::isfinite(v)) return (failure = "a value of ent_stats is not finite"), false;
        return true;
    }

    const ent_stats& stats() const { return stats_; }
    double energy() const { return stats_.kinetic_energy_J + stats_.potential_energy_J; }

    // Mixes the bits of what read() got into `hash` (FNV-1a over 64-bit words).
    void mix_into(uint64_t& hash) const {
        const auto mix = [&](double value) {
            uint64_t bits;
            std::memcpy(&bits, &value, sizeof bits);
            hash = (hash ^ bits) * 1099511628211ull;
        };
        for (double v : points_) mix(v);
        mix(stats_.kinetic_energy_J);
        mix(stats_.potential_energy_J);
        mix(stats_.max_penetration_m);
    }

private:
    ent_scene* scene_;
    ent_stats stats_{};
    std::vector<double> points_;
    std::vector<double> axis_;
};

}  // namespace

RunResult run(const HardCase& hard_case, double seconds) {
    RunResult result;
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<ent_scene, SceneDeleter> scene(hard_case.make());
    if (!scene) {
        result.failure = std::string("creating the scene failed: ") + ent_last_error();
        return result;
    }
    Checker checker(scene.get());
    if (!checker.read(result.failure)) return result;
    result.initial_energy_J = checker.energy();

    const std::unique_ptr<ToolDriver> tools = hard_case.driver ? hard_case.driver() : nullptr;
    const uint64_t steps = static_cast<uint64_t>(std::llround(seconds / hard_case.step_s));
    double time = 0.0;
    for (uint64_t i = 0; i < steps; ++i) {
        if (tools && !tools->before_step(scene.get(), time)) {
            result.failure = format("at t = %.3f s: a tool call failed: ", time) + ent_last_error();
            break;
        }
        const ent_status status = ent_scene_step(scene.get(), hard_case.step_s);
        if (status != ENT_OK) {
            result.failure = format("at t = %.3f s: ", time) + call_failure("ent_scene_step", status);
            break;
        }
        if (tools) {
            const double work = tools->work_of_step(scene.get());
            if (!std::isfinite(work)) {
                result.failure = format("at t = %.3f s: reading a tool failed: ", time) + ent_last_error();
                break;
            }
            result.external_work_J += work;
        }
        time = static_cast<double>(i + 1) * hard_case.step_s;
        if (!checker.read(result.failure)) {
            result.failure = format("at t = %.3f s: ", time) + result.failure;
            break;
        }
        checker.mix_into(result.trajectory_hash);
        const ent_stats& s = checker.stats();
        const bool settled = time >= hard_case.settle_s;
        if (settled) result.max_penetration_m = std::max(result.max_penetration_m, s.max_penetration_m);
        result.max_contacts = std::max(result.max_contacts, s.contacts);
        const double excess = checker.energy() - result.initial_energy_J - result.external_work_J;
        result.max_energy_excess_J = std::max(result.max_energy_excess_J, excess);
        // A bound of 0 means no contact at all.
        const double bound = hard_case.max_penetration_m;
        if (settled && !(s.max_penetration_m <= bound)) {
            result.failure = format("at t = %.3f s: penetration %.3g m exceeds the bound %.3g m", time,
                                    s.max_penetration_m, bound);
            break;
        }
        if (excess > hard_case.energy_allowance_J) {
            result.failure = format("at t = %.3f s: energy %.6g J exceeds its initial value plus external work",
                                    time, checker.energy()) +
                             format(" (%.6g J) by %.3g J, more than the allowance %.3g J",
                                    result.initial_energy_J + result.external_work_J, excess,
                                    hard_case.energy_allowance_J);
            break;
        }
    }
    const ent_stats& s = checker.stats();
    result.simulated_s = s.time_s;
    result.steps = s.steps;
    result.substeps = s.substeps;
    result.rollbacks = s.rollbacks;
    result.final_energy_J = checker.energy();
    result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.passed = result.failure.empty();
    return result;
}

std::string table_header() {
    return "| case | simulated s | steps | substeps | rollbacks | max contacts | max penetration mm (after settling) | "
           "E0 J | external work J | max energy excess J | final E - E0 J | wall s | result |\n"
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|";
}

std::string table_row(const HardCase& hard_case, const RunResult& r) {
    char row[512];
    std::snprintf(row, sizeof row,
                  "| %s | %.1f | %llu | %llu | %llu | %u | %.3f | %.4g | %.4g | %.3g | %.4g | %.1f | %s |",
                  hard_case.name, r.simulated_s, static_cast<unsigned long long>(r.steps),
                  static_cast<unsigned long long>(r.substeps), static_cast<unsigned long long>(r.rollbacks),
                  r.max_contacts, 1e3 * r.max_penetration_m, r.initial_energy_J, r.external_work_J,
                  r.max_energy_excess_J, r.final_energy_J - r.initial_energy_J, r.wall_s,
                  r.passed ? "pass" : "FAIL");
    return row;
}

}  // namespace stability
