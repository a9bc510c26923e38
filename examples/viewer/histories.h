// SPDX-License-Identifier: Apache-2.0
// What the panels plot and summarise, fed once a frame from the session: the force on
// each tool over the last seconds (every step, its largest magnitude per plot point, so
// no peak is lost), the step times of the last second (median and largest), the frame
// rate, the real-time factor, and each effect's cost per step over the last second.
#pragma once

#include <enteron/enteron.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "session.h"

namespace viewer {

// The last N values in a circle, laid out for ImGui::PlotLines (values, count, offset).
class Series {
public:
    explicit Series(std::size_t capacity) : values_(capacity, 0.0f) {}
    void push(float value) {
        values_[next_] = value;
        next_ = (next_ + 1) % values_.size();
        if (count_ < values_.size()) ++count_;
    }
    void clear() { next_ = count_ = 0; }
    const float* data() const { return values_.data(); }
    int size() const { return static_cast<int>(count_ < values_.size() ? count_ : values_.size()); }
    // Offset of the oldest value when the circle is full.
    int offset() const { return count_ < values_.size() ? 0 : static_cast<int>(next_); }
    float largest() const;

private:
    std::vector<float> values_;
    std::size_t next_ = 0, count_ = 0;
};

struct EffectCost {
    bool enabled = false;
    double us_per_step = 0.0;   // over the last second
    std::uint64_t calls = 0;
};

class Histories {
public:
    static constexpr double kPlotSeconds = 5.0;       // the force plot's window, s (simulated)
    static constexpr std::size_t kPlotPoints = 500;   // points in it: one per 10 ms

    Histories();
    void clear();
    // Once a frame, after Session::read.
    void add(const FrameState& frame);

    Series force_magnitude[kMaxTools];   // |F| per plot point, N
    Series force_x, force_y, force_z;    // the active tool's components, N (same points)
    std::uint32_t plotted_tool = 0;      // which tool force_x/y/z follow
    double step_median_us = 0.0, step_max_us = 0.0;  // over the last second of steps
    double frame_rate_hz = 0.0;
    double real_time_factor = 0.0;       // simulated s per wall s, over the last half second
    EffectCost effects[ENT_EFFECT_COUNT];
    double skin_update_ms = 0.0;         // average over the last second

    // Over the whole run, for the summary line that tests read.
    std::uint64_t samples = 0, nonzero_samples = 0;
    double largest_force_N = 0.0, first_contact_time_s = -1.0;

private:
    using Clock = std::chrono::steady_clock;
    void add_step(const StepSample& step);
    void close_plot_point();

    std::vector<float> recent_steps_us_;        // the last second of step times
    std::vector<float> sorted_steps_us_;        // a copy for the median
    std::size_t recent_next_ = 0;
    float bucket_max_[kMaxTools] = {};
    float bucket_force_[3] = {};                // the active tool's force at its largest
    double bucket_end_s_ = -1.0;
    Clock::time_point last_frame_, window_start_;
    double window_time_s_ = 0.0;
    int window_frames_ = 0;
    double window_skin_ms_ = 0.0;
    std::uint64_t window_steps_ = 0;            // the snapshot's step count at the window's start
    ent_effect_stats window_effects_[ENT_EFFECT_COUNT]{};
    bool started_ = false;
};

}  // namespace viewer
