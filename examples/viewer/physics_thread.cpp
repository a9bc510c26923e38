// SPDX-License-Identifier: Apache-2.0
#include "physics_thread.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "key_path.h"

namespace viewer {

namespace {

using Clock = std::chrono::steady_clock;

// The physics thread wakes once a millisecond (the haptic rate) and makes the steps the
// clock allows; it may make at most this many in one tick before it looks at the controls again.
constexpr int kMaxStepsPerTick = 50;
// Further behind the wall clock than this, it gives up catching up: the simulation then
// runs slower than real time (the real-time factor shows it) instead of in bursts.
constexpr double kMaxLagS = 0.05;

double seconds_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

}  // namespace

PhysicsThread::PhysicsThread(const PhysicsSettings& settings)
    : settings_(settings),
      paused_(settings.paused),
      rate_(settings.rate),
      step_s_(settings.step_s),
      gate_s_(settings.gate_s) {
    ent_stats stats{};
    stats.struct_size = sizeof stats;
    if (ent_scene_stats(settings_.scene, &stats) == ENT_OK) time_s_ = stats.time_s;
    report_.time_s = time_s_;
    report_.tool_count = settings_.tool_count;
    for (std::uint32_t i = 0; i < settings_.tool_count; ++i) {
        report_.tools[i].pose = settings_.initial[i];
        latest_commands_.target[i] = settings_.initial[i];
    }
    latest_commands_.count = settings_.tool_count;
    // A scripted organ moves from where the scene put it.
    obstacle_starts_.resize(settings_.obstacle_paths.size());
    for (std::size_t i = 0; i < settings_.obstacle_paths.size(); ++i) {
        ObstacleStart& start = obstacle_starts_[i];
        const ent_status status = ent_obstacle_pose(settings_.scene, settings_.obstacle_paths[i].obstacle,
                                                    start.position_m, start.orientation_wxyz);
        if (status != ENT_OK) fail("ent_obstacle_pose", status);
    }
    reports_.publish(report_);
    thread_ = std::thread([this] { run(); });
}

PhysicsThread::~PhysicsThread() {
    stop_.store(true);
    thread_.join();
}

void PhysicsThread::run() {
    auto next_tick = Clock::now();
    auto anchor_wall = next_tick;  // the wall time at which the simulation was at anchor_time_s
    double anchor_time_s = time_s_;
    double anchor_rate = rate_.load();
    bool anchor_paused = paused_.load();
    bool anchor_capture = std::isfinite(gate_s_.load());
    while (!stop_.load(std::memory_order_relaxed)) {
        ToolCommands fresh;
        if (commands_.take(fresh)) latest_commands_ = fresh;
        const double dt = step_s_.load();
        const double rate = rate_.load();
        const double gate = gate_s_.load();
        const bool paused = paused_.load();
        const auto now = Clock::now();
        // Real time: the simulation may be at anchor_time + rate x (wall time since anchor).
        // A change of rate, a pause or the end of a gate moves the anchor to now, so none of
        // them makes a jump.
        const bool capture = std::isfinite(gate);
        if (rate != anchor_rate || paused != anchor_paused || paused || capture != anchor_capture) {
            anchor_wall = now;
            anchor_time_s = time_s_;
            anchor_rate = rate;
            anchor_paused = paused;
            anchor_capture = capture;
        }
        const double allowed_s = capture ? gate : anchor_time_s + rate * seconds_between(anchor_wall, now);
        const double tolerance_s = 1e-6 * dt;  // the sum of many dt is not exactly a multiple of dt
        int steps = 0;
        if (!paused) {
            while (time_s_ + dt <= allowed_s + tolerance_s && steps < kMaxStepsPerTick &&
                   !paused_.load(std::memory_order_relaxed)) {
                step(dt);
                ++steps;
            }
        }
        for (int n = single_steps_.exchange(0); n > 0 && paused_.load(); --n) step(dt);
        const bool behind = !paused_.load() && time_s_ + dt <= allowed_s + tolerance_s;
        if (!capture && behind && allowed_s - time_s_ > kMaxLagS) {
            anchor_wall = Clock::now();  // drop the debt: run slower than real time
            anchor_time_s = time_s_;
        }
        report_.time_s = time_s_;
        report_.paused = paused_.load();
        report_.gate_reached_s = capture && !behind ? gate : -1.0;
        reports_.publish(report_);
        if (behind && (capture || steps == kMaxStepsPerTick)) continue;  // more to do now
        // Absolute schedule; a tick missed (a slow step, a busy machine) restarts it from
        // now rather than running the missed ticks in a burst.
        next_tick += std::chrono::microseconds(1000);
        const auto after = Clock::now();
        if (next_tick < after) next_tick = after;
        std::this_thread::sleep_until(next_tick);
    }
}

void PhysicsThread::step(double dt_s) {
    apply_tools(time_s_ + dt_s, dt_s);
    apply_obstacles(time_s_ + dt_s);
    const auto start = Clock::now();
    const ent_status status = ent_scene_step(settings_.scene, dt_s);
    const auto end = Clock::now();
    if (status != ENT_OK) {
        // The scene is exactly as before the call: stop here and let the user see why.
        fail("ent_scene_step", status);
        paused_.store(true);
        return;
    }
    time_s_ += dt_s;
    ++report_.steps;
    StepSample sample;
    sample.time_s = time_s_;
    sample.step_us = static_cast<float>(1e6 * seconds_between(start, end));
    read_tools(sample);
    samples_.push(sample);
}

void PhysicsThread::apply_tools(double time_after_s, double dt_s) {
    for (std::uint32_t i = 0; i < settings_.tool_count && i < latest_commands_.count; ++i) {
        ToolPose pose;
        if (i == 0 && !settings_.tool0_path.empty()) {
            // A recorded path is played as it is (its speed is the recording's).
            const double* orientation = latest_commands_.target[0].orientation_wxyz;
            std::copy(orientation, orientation + 4, pose.orientation_wxyz);
            path_at(settings_.tool0_path.data(), settings_.tool0_path.size() / 4, time_after_s, pose.position_m);
        } else {
            pose = follow(report_.tools[i].pose, latest_commands_.target[i], dt_s,
                          latest_commands_.max_speed_m_per_s, latest_commands_.max_turn_rad_per_s);
        }
        const auto id = static_cast<std::int32_t>(i);
        const ent_status status = ent_tool_set_pose(settings_.scene, id, pose.position_m, pose.orientation_wxyz);
        if (status != ENT_OK) {
            fail("ent_tool_set_pose", status);
            continue;
        }
        report_.tools[i].pose = pose;
    }
}

void PhysicsThread::apply_obstacles(double time_after_s) {
    for (std::size_t i = 0; i < settings_.obstacle_paths.size(); ++i) {
        const ObstaclePath& path = settings_.obstacle_paths[i];
        const ObstacleStart& start = obstacle_starts_[i];
        const ent_status status = obstacle_follow_path(settings_.scene, path.obstacle, start.position_m,
                                                       start.orientation_wxyz, path.keys.data(), path.keys.size() / 4,
                                                       time_after_s);
        if (status != ENT_OK) fail("ent_obstacle_set_pose", status);
    }
}

void PhysicsThread::read_tools(StepSample& sample) {
    for (std::uint32_t i = 0; i < settings_.tool_count; ++i) {
        ent_tool_feedback& feedback = report_.tools[i].feedback;
        feedback.struct_size = sizeof feedback;
        const ent_status status = ent_tool_read_feedback(settings_.scene, static_cast<std::int32_t>(i), &feedback);
        if (status != ENT_OK) {
            fail("ent_tool_read_feedback", status);
            continue;
        }
        for (int c = 0; c < 3; ++c) sample.force_N[i][c] = static_cast<float>(feedback.force_N[c]);
    }
}

void PhysicsThread::fail(const char* call, ent_status status) {
    ++report_.failures;
    report_.last_status = status;
    report_.last_failure_time_s = time_s_;
    std::snprintf(report_.last_call, sizeof report_.last_call, "%s", call);
    std::snprintf(report_.last_message, sizeof report_.last_message, "%s", ent_last_error());
}

}  // namespace viewer
