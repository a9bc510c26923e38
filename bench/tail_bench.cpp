// SPDX-License-Identifier: Apache-2.0
// The tail of the step time: every step of a long run at 1 kHz, as a haptic loop runs them,
// and for each slow one what it did, so that the slow steps the library causes can be told
// from those the machine causes (docs/performance.md, "The tail").
//
// Two scenes, each with and without a render thread:
//   pile     the demo pile with a tool (pile_with_tool.h): the 6 m bowel settled in the
//            30 cm cavity, a grasper pressed 5 mm into it sliding at 1 Hz;
//   abdomen  examples/scenes/abdomen.json with its two tools, the retractor that lifts the
//            liver and the grasper that goes down into the coils (examples/abdomen_motion.h),
//            played as a cycle: lift and press, hold, withdraw, lower, again.
// The physics thread is pinned to one core (sched_setaffinity) and steps 1 ms at a time,
// paced by the wall clock (a step late for its tick counts a missed deadline; the ticks it
// overran are skipped, as a haptic loop would). The render thread, when on, is pinned to
// the other core and updates a convolution skin (the default resolution) at 60 Hz.
//
// Around each step, outside the timed interval: getrusage(RUSAGE_THREAD) (page faults,
// minor and major; involuntary context switches) and the thread's CPU clock. The step's
// own counters come from ent_stats (attempts, substeps, the proxies' iterations and
// evaluations, contacts, full contact searches). A step whose wall time is far above its
// CPU time waited for the core (preempted); one whose CPU time is high did more work or
// ran slower (page faults, cold caches); the counters say which work.
//
//   enteron_tail_bench [--scene pile|abdomen|all] [--render off|on|both] [--seconds S]
//                      [--control-points N] [--cpu C] [--render-cpu C] [--realtime P]
//                      [--unpaced] [--slow-csv DIR] [--abdomen-scene FILE]
//
// --cpu -1 and --render-cpu -1 leave a thread unpinned (the smoke test, on any machine).
// Default: both scenes, both render settings, 600 s (10 simulated minutes) each. Prints
// markdown tables (scripts/bench-tail writes them to bench/results/tail.md). --seconds 3
// is a smoke run (ctest tail_bench.smoke). Exit 1 if a call fails.
#include <enteron/enteron.h>

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bowel_scene.h"
#include "key_path.h"
#include "abdomen_motion.h"
#include "pile_with_tool.h"
#include "step_timing.h"

namespace {

using namespace enteron::bench;

struct Options {
    std::string scene = "all";
    std::string render = "both";
    double seconds = 600.0;
    uint32_t control_points = 240;
    int cpu = 0;
    int render_cpu = 1;
    int realtime = 0;  // SCHED_FIFO priority of the physics thread; 0: normal scheduling
    bool paced = true;
    std::string slow_csv_dir;  // empty: no CSV of the slow steps
    std::string abdomen_scene = "examples/scenes/abdomen.json";
};

// What one step did and what it cost.
struct StepRecord {
    double wall_us = 0.0;
    double cpu_us = 0.0;
    uint32_t attempts = 0;
    uint32_t substeps = 0;
    uint32_t proxy_iterations = 0;
    uint32_t proxy_evaluations = 0;
    uint32_t contacts = 0;
    uint32_t minor_faults = 0;
    uint32_t major_faults = 0;
    uint32_t preemptions = 0;  // involuntary context switches
    uint32_t full_searches = 0;
};

constexpr double kSlowUs = 500.0;
constexpr double kVerySlowUs = 1000.0;

double now_s(clockid_t clock) {
    timespec t;
    clock_gettime(clock, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

timespec timespec_at(double seconds) {
    timespec t;
    t.tv_sec = static_cast<time_t>(std::floor(seconds));
    t.tv_nsec = static_cast<long>((seconds - std::floor(seconds)) * 1e9);
    return t;
}

// Pins the calling thread to `cpu` (a negative cpu: leaves it where it is); false (and
// errno's message) if the kernel refuses.
bool pin_to_cpu(int cpu, std::string* error) {
    if (cpu < 0) return true;
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    if (sched_setaffinity(0, sizeof set, &set) == 0) return true;
    *error = "sched_setaffinity(cpu " + std::to_string(cpu) + "): " + std::strerror(errno);
    return false;
}

// A scene and what drives it before each step.
class Scenario {
public:
    virtual ~Scenario() { ent_scene_destroy(scene_); }
    ent_scene* scene() const { return scene_; }
    // Sets the tools' and obstacles' poses for the step that ends at time_s. False on failure.
    virtual bool drive(double time_s, std::string* error) = 0;
    virtual std::string description() const = 0;

protected:
    ent_scene* scene_ = nullptr;
};

// The demo pile with a tool (pile_with_tool.h).
class PileScenario final : public Scenario {
public:
    bool create(uint32_t control_points, std::string* error) {
        const std::vector<double>& pile = settled_pile(control_points, error);
        if (pile.empty()) return false;
        scene_ = bowel_in_cavity(ENT_INTEGRATOR_IMPLICIT_EULER, control_points, pile, 0, error);
        if (scene_ == nullptr) return false;
        ent_tool_desc tool;
        ent_tool_desc_default(&tool);
        tool_.reset(new PileTool(pile, pile_bowel_desc(ENT_INTEGRATOR_IMPLICIT_EULER, control_points).radius_m,
                                 tool.radius_m));
        tool_->position_at(pile, 0.0, tool.position_m);
        const ent_status status = ent_tool_add(scene_, &tool, &tool_id_);
        if (status != ENT_OK) *error = last_error("ent_tool_add", status);
        points_ = pile;
        control_points_ = control_points;
        return status == ENT_OK;
    }
    bool drive(double time_s, std::string* error) override {
        uint32_t count = 0;
        ent_status status = ent_scene_control_points(scene_, control_points_, points_.data(), &count);
        double position[3];
        const double upright[4] = {1.0, 0.0, 0.0, 0.0};
        tool_->position_at(points_, time_s, position);
        if (status == ENT_OK) status = ent_tool_set_pose(scene_, tool_id_, position, upright);
        if (status != ENT_OK) *error = last_error("ent_scene_control_points / ent_tool_set_pose", status);
        return status == ENT_OK;
    }
    std::string description() const override {
        return "pile, N = " + std::to_string(control_points_) + ", implicit Euler";
    }

private:
    std::unique_ptr<PileTool> tool_;
    std::vector<double> points_;
    uint32_t control_points_ = 0;
    int32_t tool_id_ = -1;
};

// The abdomen's retractor and grasper as a cycle of kCyclePeriodS from kCycleStartS on
// (before it, the bowel settles: abdomen_motion.h's first second). Its first 1.5 s are
// abdomen_motion.h's motion from 1 s on: the liver lifted 4 cm in 0.5 s, the grasper over
// the bowel and 41 cm down into the coils by 1.5 s; then it holds 1.5 s, rises in 1 s,
// goes back to where it started, and the liver is lowered, ready for the next cycle.
constexpr double kCycleStartS = 1.0;
constexpr double kCyclePeriodS = 6.0;
constexpr double kCycleToolKeys[] = {0.0, -0.1, -0.05, 0.3,  0.5, -0.06, -0.05, 0.3,   1.5, -0.06, -0.05, -0.11,
                                     3.0, -0.06, -0.05, -0.11, 4.0, -0.06, -0.05, 0.3, 4.5, -0.1, -0.05, 0.3,
                                     6.0, -0.1, -0.05, 0.3};
constexpr double kCycleLiverKeys[] = {0.0, 0.0, 0.0, 0.0,  0.5, 0.0, 0.0, 0.04, 4.5, 0.0, 0.0, 0.04,
                                      5.5, 0.0, 0.0, 0.0,  6.0, 0.0, 0.0, 0.0};
constexpr std::size_t kCycleToolKeyCount = sizeof kCycleToolKeys / (4 * sizeof(double));
constexpr std::size_t kCycleLiverKeyCount = sizeof kCycleLiverKeys / (4 * sizeof(double));

class AbdomenScenario final : public Scenario {
public:
    bool create(const std::string& path, std::string* error) {
        ent_status status = ent_scene_create_json_file(path.c_str(), nullptr, &scene_);
        if (status != ENT_OK) {
            *error = last_error(("ent_scene_create_json_file(" + path + ")").c_str(), status);
            return false;
        }
        status = ent_obstacle_pose(scene_, ABDOMEN_LIVER, liver_at_, liver_orientation_);
        if (status != ENT_OK) *error = last_error("ent_obstacle_pose", status);
        return status == ENT_OK;
    }
    bool drive(double time_s, std::string* error) override {
        double tool_keys_time = time_s, liver_keys_time = time_s;
        const double* tool_keys = abdomen_tool_keys;
        std::size_t tool_key_count = ABDOMEN_TOOL_KEY_COUNT;
        const double* liver_keys = abdomen_liver_keys;
        std::size_t liver_key_count = ABDOMEN_LIVER_KEY_COUNT;
        if (time_s > kCycleStartS) {
            tool_keys_time = liver_keys_time = std::fmod(time_s - kCycleStartS, kCyclePeriodS);
            tool_keys = kCycleToolKeys;
            tool_key_count = kCycleToolKeyCount;
            liver_keys = kCycleLiverKeys;
            liver_key_count = kCycleLiverKeyCount;
        }
        ent_status status = obstacle_follow_path(scene_, ABDOMEN_LIVER, liver_at_, liver_orientation_, liver_keys,
                                                 liver_key_count, liver_keys_time);
        double tip[3];
        path_at(tool_keys, tool_key_count, tool_keys_time, tip);
        const double upright[4] = {1.0, 0.0, 0.0, 0.0};
        if (status == ENT_OK) status = ent_tool_set_pose(scene_, 0, tip, upright);
        if (status != ENT_OK) *error = last_error("ent_obstacle_set_pose / ent_tool_set_pose", status);
        return status == ENT_OK;
    }
    std::string description() const override { return "abdomen (abdomen.json: organ meshes, retractor, grasper)"; }

private:
    double liver_at_[3] = {0.0, 0.0, 0.0};
    double liver_orientation_[4] = {1.0, 0.0, 0.0, 0.0};
};

// The render thread: a convolution skin updated at 60 Hz on its own core until stopped.
class RenderThread {
public:
    bool start(ent_scene* scene, int cpu, std::string* error) {
        ent_skin_desc desc;
        ent_skin_desc_default(&desc);
        desc.method = ENT_SKIN_CONVOLUTION;
        const ent_status status = ent_skin_create(scene, &desc, &skin_);
        if (status != ENT_OK) {
            *error = last_error("ent_skin_create", status);
            return false;
        }
        update_us_.reserve(1 << 16);
        thread_ = std::thread([this, cpu] { run(cpu); });
        return true;
    }
    // Stops the thread; false if it failed (the message in *error).
    bool stop(std::string* error) {
        if (!thread_.joinable()) return true;
        stop_.store(true);
        thread_.join();
        ent_skin_destroy(skin_);
        skin_ = nullptr;
        if (!failure_.empty()) *error = failure_;
        return failure_.empty();
    }
    ~RenderThread() {
        std::string ignored;
        stop(&ignored);
    }
    std::vector<double>& update_us() { return update_us_; }
    uint64_t triangles() const { return triangles_; }

private:
    void run(int cpu) {
        std::string error;
        if (!pin_to_cpu(cpu, &error)) failure_ = error;
        const double period = 1.0 / 60.0;
        double next = now_s(CLOCK_MONOTONIC);
        while (!stop_.load()) {
            next += period;
            const timespec wake = timespec_at(next);
            clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &wake, nullptr);
            const double start = now_s(CLOCK_MONOTONIC);
            ent_mesh_view mesh;
            std::memset(&mesh, 0, sizeof mesh);
            mesh.struct_size = sizeof mesh;
            ent_status status = ent_skin_update(skin_);
            if (status == ENT_OK) status = ent_skin_mesh(skin_, &mesh);
            if (status != ENT_OK) {
                if (failure_.empty()) failure_ = last_error("ent_skin_update / ent_skin_mesh", status);
                return;
            }
            update_us_.push_back(1e6 * (now_s(CLOCK_MONOTONIC) - start));
            triangles_ = mesh.triangle_count;
            next = std::max(next, now_s(CLOCK_MONOTONIC) - period);  // a late frame is skipped, not caught up
        }
    }

    ent_skin* skin_ = nullptr;
    std::thread thread_;
    std::atomic<bool> stop_{false};
    std::vector<double> update_us_;
    uint64_t triangles_ = 0;
    std::string failure_;
};

struct RunResult {
    std::string scene;
    bool render = false;
    std::vector<StepRecord> steps;
    uint64_t missed_deadlines = 0;
    std::vector<double> render_update_us;
    uint64_t render_triangles = 0;
    ent_stats final_stats{};
    double load_before[3] = {0, 0, 0};
    double load_after[3] = {0, 0, 0};
    double wall_s = 0.0;
};

void load_average(double out[3]) {
    if (getloadavg(out, 3) != 3) out[0] = out[1] = out[2] = -1.0;
}

// The timed steps: its own function so that a profiler can be told to count these steps
// only (valgrind --tool=callgrind --toggle-collect='*timed_steps*', docs/performance.md).
__attribute__((noinline)) bool timed_steps(Scenario& scenario, const Options& options, double start_time_s,
                                           RunResult& result, std::string* error) {
    const std::size_t steps = static_cast<std::size_t>(std::llround(options.seconds / kStepS));
    result.steps.assign(steps, StepRecord{});  // touched here: no page fault of ours in the loop
    ent_stats before_stats{};
    if (!read_stats(scenario.scene(), &before_stats)) {
        *error = "ent_scene_stats failed";
        return false;
    }
    uint64_t full_searches = before_stats.full_contact_searches;
    double next_tick = now_s(CLOCK_MONOTONIC);
    for (std::size_t k = 0; k < steps; ++k) {
        const double time_s = start_time_s + static_cast<double>(k + 1) * kStepS;
        if (!scenario.drive(time_s, error)) return false;
        rusage usage_before, usage_after;
        getrusage(RUSAGE_THREAD, &usage_before);
        const double cpu_before = now_s(CLOCK_THREAD_CPUTIME_ID);
        const double wall_before = now_s(CLOCK_MONOTONIC);
        const ent_status status = ent_scene_step(scenario.scene(), kStepS);
        const double wall_after = now_s(CLOCK_MONOTONIC);
        const double cpu_after = now_s(CLOCK_THREAD_CPUTIME_ID);
        getrusage(RUSAGE_THREAD, &usage_after);
        if (status != ENT_OK) {
            *error = last_error("ent_scene_step", status) + " (t = " + std::to_string(time_s) + " s)";
            return false;
        }
        ent_stats stats{};
        read_stats(scenario.scene(), &stats);
        StepRecord& record = result.steps[k];
        record.wall_us = 1e6 * (wall_after - wall_before);
        record.cpu_us = 1e6 * (cpu_after - cpu_before);
        record.attempts = stats.last_step_attempts;
        record.substeps = stats.last_step_substeps;
        record.proxy_iterations = stats.last_step_proxy_iterations;
        record.proxy_evaluations = stats.last_step_proxy_evaluations;
        record.contacts = stats.contacts;
        record.minor_faults = static_cast<uint32_t>(usage_after.ru_minflt - usage_before.ru_minflt);
        record.major_faults = static_cast<uint32_t>(usage_after.ru_majflt - usage_before.ru_majflt);
        record.preemptions = static_cast<uint32_t>(usage_after.ru_nivcsw - usage_before.ru_nivcsw);
        record.full_searches = static_cast<uint32_t>(stats.full_contact_searches - full_searches);
        full_searches = stats.full_contact_searches;
        if (!options.paced) continue;
        // The next tick; a step that ran past it missed its deadline, and the ticks it
        // overran are skipped.
        next_tick += kStepS;
        const double now = now_s(CLOCK_MONOTONIC);
        if (now > next_tick) {
            result.missed_deadlines += 1;
            next_tick += std::ceil((now - next_tick) / kStepS) * kStepS;
        }
        const timespec wake = timespec_at(next_tick);
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &wake, nullptr);
    }
    return true;
}

// One scene, with or without the render thread.
bool run(const std::string& scene_name, bool render, const Options& options, RunResult& result, std::string* error) {
    result.scene = scene_name;
    result.render = render;
    std::unique_ptr<Scenario> scenario;
    double start_time_s = 0.0;
    if (scene_name == "pile") {
        auto pile = std::make_unique<PileScenario>();
        if (!pile->create(options.control_points, error)) return false;
        scenario = std::move(pile);
    } else {
        auto abdomen = std::make_unique<AbdomenScenario>();
        if (!abdomen->create(options.abdomen_scene, error)) return false;
        scenario = std::move(abdomen);
        // The bowel settles (untimed) during the motion's first second.
        for (; start_time_s < kCycleStartS - 0.5 * kStepS; start_time_s += kStepS) {
            if (!scenario->drive(start_time_s + kStepS, error)) return false;
            const ent_status status = ent_scene_step(scenario->scene(), kStepS);
            if (status != ENT_OK) {
                *error = last_error("ent_scene_step (settling)", status);
                return false;
            }
        }
    }
    result.scene = scenario->description();
    if (!pin_to_cpu(options.cpu, error)) return false;
    if (options.realtime > 0) {
        sched_param parameter{};
        parameter.sched_priority = options.realtime;
        if (sched_setscheduler(0, SCHED_FIFO, &parameter) != 0) {
            *error = std::string("sched_setscheduler(SCHED_FIFO, ") + std::to_string(options.realtime) +
                     "): " + std::strerror(errno) + " (needs root or CAP_SYS_NICE)";
            return false;
        }
    }
    RenderThread renderer;
    if (render && !renderer.start(scenario->scene(), options.render_cpu, error)) return false;
    load_average(result.load_before);
    const double wall_start = now_s(CLOCK_MONOTONIC);
    const bool stepped = timed_steps(*scenario, options, start_time_s, result, error);
    result.wall_s = now_s(CLOCK_MONOTONIC) - wall_start;
    load_average(result.load_after);
    if (options.realtime > 0) {
        sched_param parameter{};
        sched_setscheduler(0, SCHED_OTHER, &parameter);
    }
    std::string render_error;
    const bool rendered = renderer.stop(&render_error);
    if (stepped && !rendered) *error = render_error;
    result.render_update_us = std::move(renderer.update_us());
    result.render_triangles = renderer.triangles();
    read_stats(scenario->scene(), &result.final_stats);
    return stepped && rendered;
}

std::string format_us(double us) {
    char text[32];
    std::snprintf(text, sizeof text, us >= 100.0 ? "%.0f" : "%.1f", us);
    return text;
}

void print_distribution(const std::vector<RunResult>& results, const Options& options) {
    std::printf("| scene | render thread | steps | median us | p99 | p99.9 | p99.99 | largest | over 0.5 ms | "
                "over 1 ms | missed deadlines | median CPU us | load average (before / after) |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (const RunResult& r : results) {
        std::vector<double> wall, cpu;
        wall.reserve(r.steps.size());
        cpu.reserve(r.steps.size());
        for (const StepRecord& s : r.steps) {
            wall.push_back(s.wall_us);
            cpu.push_back(s.cpu_us);
        }
        std::sort(wall.begin(), wall.end());
        std::sort(cpu.begin(), cpu.end());
        const auto over = [&](double us) { return wall.end() - std::upper_bound(wall.begin(), wall.end(), us); };
        std::printf("| %s | %s | %zu | %s | %s | %s | %s | %s | %td | %td | %s | %s | %.1f / %.1f |\n", r.scene.c_str(),
                    r.render ? "convolution skin, 60 Hz" : "none", wall.size(), format_us(quantile(wall, 0.5)).c_str(),
                    format_us(quantile(wall, 0.99)).c_str(), format_us(quantile(wall, 0.999)).c_str(),
                    format_us(quantile(wall, 0.9999)).c_str(), format_us(wall.back()).c_str(), over(kSlowUs),
                    over(kVerySlowUs), options.paced ? std::to_string(r.missed_deadlines).c_str() : "(unpaced)",
                    format_us(quantile(cpu, 0.5)).c_str(), r.load_before[0], r.load_after[0]);
    }
}

// The slow steps (over 0.5 ms) by what they did: more than one attempt, a full contact
// search, page faults, preempted (an involuntary context switch), or none of those with a
// CPU time over 0.5 ms (the step's own work, or a slow core: cache misses, a busy sibling).
void print_slow_causes(const std::vector<RunResult>& results) {
    std::printf("| scene | render thread | slow steps | > 1 attempt | full contact search | page faults (minor / major) | "
                "preempted | CPU time > 0.5 ms | none of these | median step's contacts / proxy iterations | slow steps' contacts / proxy iterations (median) |\n");
    std::printf("|---|---|---:|---:|---:|---|---:|---:|---:|---|---|\n");
    for (const RunResult& r : results) {
        uint64_t slow = 0, attempts = 0, searches = 0, faulted = 0, minor = 0, major = 0, preempted = 0, busy = 0,
                 other = 0;
        std::vector<double> slow_contacts, slow_proxy, all_contacts, all_proxy;
        for (const StepRecord& s : r.steps) {
            all_contacts.push_back(s.contacts);
            all_proxy.push_back(s.proxy_iterations);
            if (!(s.wall_us > kSlowUs)) continue;
            slow += 1;
            attempts += s.attempts > 1 ? 1 : 0;
            searches += s.full_searches > 0 ? 1 : 0;
            faulted += s.minor_faults + s.major_faults > 0 ? 1 : 0;
            minor += s.minor_faults;
            major += s.major_faults;
            preempted += s.preemptions > 0 ? 1 : 0;
            busy += s.cpu_us > kSlowUs ? 1 : 0;
            other += s.attempts <= 1 && s.full_searches == 0 && s.minor_faults + s.major_faults == 0 &&
                             s.preemptions == 0 && !(s.cpu_us > kSlowUs)
                         ? 1
                         : 0;
            slow_contacts.push_back(s.contacts);
            slow_proxy.push_back(s.proxy_iterations);
        }
        std::sort(all_contacts.begin(), all_contacts.end());
        std::sort(all_proxy.begin(), all_proxy.end());
        std::sort(slow_contacts.begin(), slow_contacts.end());
        std::sort(slow_proxy.begin(), slow_proxy.end());
        const std::string slow_medians =
            slow > 0 ? format_us(quantile(slow_contacts, 0.5)) + " / " + format_us(quantile(slow_proxy, 0.5)) : "-";
        std::printf("| %s | %s | %llu | %llu | %llu | %llu steps (%llu / %llu faults) | %llu | %llu | %llu | %s / %s | %s |\n",
                    r.scene.c_str(), r.render ? "on" : "none", (unsigned long long)slow, (unsigned long long)attempts,
                    (unsigned long long)searches, (unsigned long long)faulted, (unsigned long long)minor,
                    (unsigned long long)major, (unsigned long long)preempted, (unsigned long long)busy,
                    (unsigned long long)other, format_us(quantile(all_contacts, 0.5)).c_str(),
                    format_us(quantile(all_proxy, 0.5)).c_str(), slow_medians.c_str());
    }
}

void print_record_header() {
    std::printf("| step | wall us | CPU us | attempts | substeps | proxy iterations | proxy evaluations | contacts | "
                "page faults (minor / major) | preempted | full contact search |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n");
}

void print_record(std::size_t index, const StepRecord& s) {
    std::printf("| %zu | %s | %s | %u | %u | %u | %u | %u | %u / %u | %u | %u |\n", index, format_us(s.wall_us).c_str(),
                format_us(s.cpu_us).c_str(), s.attempts, s.substeps, s.proxy_iterations, s.proxy_evaluations,
                s.contacts, s.minor_faults, s.major_faults, s.preemptions, s.full_searches);
}

// The slowest steps of each run, and for comparison a step of median wall time.
void print_slowest(const std::vector<RunResult>& results, std::size_t count) {
    for (const RunResult& r : results) {
        std::vector<std::size_t> order(r.steps.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return r.steps[a].wall_us > r.steps[b].wall_us; });
        std::printf("\n%s, render thread %s: the %zu slowest steps, then the median one\n\n", r.scene.c_str(),
                    r.render ? "on" : "off", std::min(count, order.size()));
        print_record_header();
        for (std::size_t i = 0; i < std::min(count, order.size()); ++i) print_record(order[i], r.steps[order[i]]);
        if (!order.empty()) print_record(order[order.size() / 2], r.steps[order[order.size() / 2]]);
    }
}

bool write_slow_csv(const RunResult& r, const std::string& path, std::string* error) {
    FILE* file = std::fopen(path.c_str(), "w");
    if (file == nullptr) {
        *error = "cannot write " + path + ": " + std::strerror(errno);
        return false;
    }
    std::fprintf(file, "step,wall_us,cpu_us,attempts,substeps,proxy_iterations,proxy_evaluations,contacts,"
                       "minor_faults,major_faults,preemptions,full_contact_searches\n");
    for (std::size_t i = 0; i < r.steps.size(); ++i) {
        const StepRecord& s = r.steps[i];
        if (!(s.wall_us > kSlowUs)) continue;
        std::fprintf(file, "%zu,%.1f,%.1f,%u,%u,%u,%u,%u,%u,%u,%u,%u\n", i, s.wall_us, s.cpu_us, s.attempts,
                     s.substeps, s.proxy_iterations, s.proxy_evaluations, s.contacts, s.minor_faults, s.major_faults,
                     s.preemptions, s.full_searches);
    }
    return std::fclose(file) == 0;
}

int usage() {
    std::fprintf(stderr,
                 "usage: enteron_tail_bench [--scene pile|abdomen|all] [--render off|on|both] [--seconds S]\n"
                 "                          [--control-points N] [--cpu C] [--render-cpu C] [--realtime PRIORITY]\n"
                 "                          [--unpaced] [--slow-csv DIR] [--abdomen-scene FILE]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if ((ent_version() >> 16) != ENT_VERSION_MAJOR) {
        std::fprintf(stderr, "enteron_tail_bench: libenteron major version %u, built for %d\n",
                     static_cast<unsigned>(ent_version() >> 16), ENT_VERSION_MAJOR);
        return 1;
    }
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        const bool has_value = i + 1 < argc;
        if (argument == "--unpaced") {
            options.paced = false;
        } else if (!has_value) {
            return usage();
        } else if (argument == "--scene") {
            options.scene = argv[++i];
        } else if (argument == "--render") {
            options.render = argv[++i];
        } else if (argument == "--seconds") {
            options.seconds = std::atof(argv[++i]);
        } else if (argument == "--control-points") {
            options.control_points = static_cast<uint32_t>(std::atoi(argv[++i]));
        } else if (argument == "--cpu") {
            options.cpu = std::atoi(argv[++i]);
        } else if (argument == "--render-cpu") {
            options.render_cpu = std::atoi(argv[++i]);
        } else if (argument == "--realtime") {
            options.realtime = std::atoi(argv[++i]);
        } else if (argument == "--slow-csv") {
            options.slow_csv_dir = argv[++i];
        } else if (argument == "--abdomen-scene") {
            options.abdomen_scene = argv[++i];
        } else {
            return usage();
        }
    }
    const bool scene_ok = options.scene == "pile" || options.scene == "abdomen" || options.scene == "all";
    const bool render_ok = options.render == "off" || options.render == "on" || options.render == "both";
    if (!scene_ok || !render_ok || !(options.seconds >= kStepS) || options.control_points < 4 ||
        options.realtime < 0 || options.realtime > 99)
        return usage();

    std::vector<std::string> scenes;
    if (options.scene != "abdomen") scenes.push_back("pile");
    if (options.scene != "pile") scenes.push_back("abdomen");
    std::vector<bool> renders;
    if (options.render != "on") renders.push_back(false);
    if (options.render != "off") renders.push_back(true);

    std::vector<RunResult> results;
    for (const std::string& scene : scenes) {
        for (const bool render : renders) {
            std::fprintf(stderr, "enteron_tail_bench: %s, render thread %s, %g s...\n", scene.c_str(),
                         render ? "on" : "off", options.seconds);
            RunResult result;
            std::string error;
            if (!run(scene, render, options, result, &error)) {
                std::fprintf(stderr, "enteron_tail_bench: %s: %s\n", scene.c_str(), error.c_str());
                return 1;
            }
            if (!options.slow_csv_dir.empty()) {
                const std::string path =
                    options.slow_csv_dir + "/" + scene + (render ? "_render" : "") + "_slow_steps.csv";
                if (!write_slow_csv(result, path, &error)) {
                    std::fprintf(stderr, "enteron_tail_bench: %s\n", error.c_str());
                    return 1;
                }
            }
            results.push_back(std::move(result));
        }
    }

    std::printf("Step wall time, %g simulated s per run at 1 kHz (%s), physics thread on CPU %d%s; "
                "render thread (when on) on CPU %d, a convolution skin at 60 Hz.\n\n",
                options.seconds, options.paced ? "paced by the wall clock" : "unpaced: steps back to back",
                options.cpu, options.realtime > 0 ? (", SCHED_FIFO " + std::to_string(options.realtime)).c_str() : "",
                options.render_cpu);
    print_distribution(results, options);
    std::printf("\nWhat the slow steps (over 0.5 ms) did:\n\n");
    print_slow_causes(results);
    for (const RunResult& r : results) {
        if (!r.render || r.render_update_us.empty()) continue;
        std::vector<double> updates = r.render_update_us;
        const StepTimeSummary summary = summarize(updates);
        std::printf("\n%s: the render thread updated its skin %zu times (%llu triangles), median %s us, largest %s us.\n",
                    r.scene.c_str(), updates.size(), (unsigned long long)r.render_triangles,
                    format_us(summary.median_us).c_str(), format_us(summary.max_us).c_str());
    }
    for (const RunResult& r : results) {
        uint32_t most_iterations = 0, most_evaluations = 0, most_attempts = 0;
        for (const StepRecord& s : r.steps) {
            most_iterations = std::max(most_iterations, s.proxy_iterations);
            most_evaluations = std::max(most_evaluations, s.proxy_evaluations);
            most_attempts = std::max(most_attempts, s.attempts);
        }
        std::printf("\n%s, render thread %s: at most %u attempts, %u proxy iterations and %u proxy evaluations in a "
                    "step; ent_stats after the run: max_step_ns %llu, late_steps %llu, "
                    "subdivided_steps %llu, rollbacks %llu, proxy_unbalanced_solves %llu, full_contact_searches %llu.\n",
                    r.scene.c_str(), r.render ? "on" : "off", most_attempts, most_iterations, most_evaluations,
                    (unsigned long long)r.final_stats.max_step_ns,
                    (unsigned long long)r.final_stats.late_steps, (unsigned long long)r.final_stats.subdivided_steps,
                    (unsigned long long)r.final_stats.rollbacks, (unsigned long long)r.final_stats.proxy_unbalanced_solves,
                    (unsigned long long)r.final_stats.full_contact_searches);
    }
    print_slowest(results, 10);
    return 0;
}
