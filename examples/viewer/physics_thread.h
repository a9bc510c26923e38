// SPDX-License-Identifier: Apache-2.0
// The physics thread of a local session: the one thread that steps the scene. It steps at
// the scene's pace in real time (scaled by a rate for slow motion), or, for frame-exact
// captures, as fast as it can up to a gate the render thread moves. It never takes a lock
// and never waits for the render thread: commands come in and reports go out through
// LatestValue (newest wins), one StepSample per step goes out through a SampleRing, and the
// controls are atomics. The render thread reads the scene itself only through the
// published snapshot (ent_scene_stats, ent_scene_axis, ent_skin_update, ...) and posts
// only tool commands (the jaws), both of which the library makes safe beside
// ent_scene_step.
#pragma once

#include <enteron/enteron.h>

#include <atomic>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

#include "latest_value.h"
#include "sample_ring.h"
#include "tool_exchange.h"

namespace viewer {

// One step, for the plots: every step's force on every tool and the step's wall time.
struct StepSample {
    double time_s = 0.0;                 // simulated time after the step
    float step_us = 0.0f;                // wall time of ent_scene_step, us
    float force_N[kMaxTools][3] = {};    // on each tool, N
};

// The physics thread's state after its last tick.
struct PhysicsReport {
    double time_s = 0.0;                 // simulated time after the last step
    std::uint64_t steps = 0;             // steps made by this thread
    bool paused = false;
    double gate_reached_s = -1.0;        // capture: the gate it stopped at, else -1
    std::uint32_t tool_count = 0;
    ToolReadback tools[kMaxTools];
    std::uint64_t failures = 0;          // failed library calls so far
    ent_status last_status = ENT_OK;     // the last failure: its status,
    char last_call[32] = "";             // the call,
    char last_message[256] = "";         // its ent_last_error(),
    double last_failure_time_s = 0.0;    // and when
};

// A scripted path for tool 0, 4 doubles per key (t_s, x, y, z in m), like a haptic device
// playing a recording.
using ToolPathKeys = std::vector<double>;

// A scripted motion of an obstacle (a retractor lifting the liver): its frame's origin
// displaced from where the scene put it, 4 doubles per key (t_s, dx, dy, dz in m), its
// orientation kept.
struct ObstaclePath {
    std::int32_t obstacle = -1;
    std::vector<double> keys;
};

struct PhysicsSettings {
    ent_scene* scene = nullptr;          // driven by this thread only while it runs
    std::uint32_t tool_count = 0;        // tools to drive, <= kMaxTools
    ToolPose initial[kMaxTools];         // their poses in the scene description
    ToolPathKeys tool0_path;             // if not empty, tool 0 follows it, not the commands
    std::vector<ObstaclePath> obstacle_paths;  // played before every step (ent_obstacle_set_pose)
    double step_s = 0.001;               // dt of each ent_scene_step
    double rate = 1.0;                   // simulated seconds per wall second
    bool paused = false;
    double gate_s = std::numeric_limits<double>::infinity();  // capture: never step past this time
};

class PhysicsThread {
public:
    static constexpr std::size_t kSampleCapacity = 8192;  // 8 s of 1 ms steps

    explicit PhysicsThread(const PhysicsSettings& settings);  // starts the thread
    ~PhysicsThread();                                          // stops it and joins
    PhysicsThread(const PhysicsThread&) = delete;
    PhysicsThread& operator=(const PhysicsThread&) = delete;

    // Controls, from any thread.
    void set_paused(bool paused) { paused_.store(paused); }
    bool paused() const { return paused_.load(); }
    void step_once() { single_steps_.fetch_add(1); }           // one step while paused
    void set_rate(double rate) { rate_.store(rate); }          // > 0
    double rate() const { return rate_.load(); }
    void set_step(double step_s) { step_s_.store(step_s); }    // > 0
    double step() const { return step_s_.load(); }
    void set_gate(double time_s) { gate_s_.store(time_s); }

    LatestValue<ToolCommands>& commands() { return commands_; }   // render thread writes
    LatestValue<PhysicsReport>& reports() { return reports_; }    // render thread reads
    SampleRing<StepSample, kSampleCapacity>& samples() { return samples_; }

private:
    void run();
    void step(double dt_s);
    void apply_tools(double time_after_s, double dt_s);
    void apply_obstacles(double time_after_s);
    void read_tools(StepSample& sample);
    void fail(const char* call, ent_status status);

    // Read only by the physics thread once it runs.
    PhysicsSettings settings_;
    ToolCommands latest_commands_;
    PhysicsReport report_;
    double time_s_ = 0.0;
    struct ObstacleStart {
        double position_m[3] = {};
        double orientation_wxyz[4] = {1, 0, 0, 0};
    };
    std::vector<ObstacleStart> obstacle_starts_;  // of each obstacle path, read at creation

    std::atomic<bool> stop_{false};
    std::atomic<bool> paused_;
    std::atomic<int> single_steps_{0};
    std::atomic<double> rate_;
    std::atomic<double> step_s_;
    std::atomic<double> gate_s_;
    LatestValue<ToolCommands> commands_;
    LatestValue<PhysicsReport> reports_;
    SampleRing<StepSample, kSampleCapacity> samples_;
    std::thread thread_;  // last: starts after everything above exists
};

}  // namespace viewer
