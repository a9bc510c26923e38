// SPDX-License-Identifier: Apache-2.0
#include "histories.h"

#include <algorithm>
#include <cmath>

namespace viewer {

namespace {
constexpr double kPlotPointS = Histories::kPlotSeconds / Histories::kPlotPoints;
constexpr std::size_t kRecentSteps = 1000;  // "the last second" at 1 kHz
constexpr double kWindowS = 0.5;            // rates are measured over this much wall time
}  // namespace

float Series::largest() const {
    float m = 0.0f;
    for (int i = 0; i < size(); ++i) m = std::max(m, values_[static_cast<std::size_t>(i)]);
    return m;
}

Histories::Histories()
    : force_magnitude{Series(kPlotPoints), Series(kPlotPoints), Series(kPlotPoints), Series(kPlotPoints)},
      force_x(kPlotPoints),
      force_y(kPlotPoints),
      force_z(kPlotPoints) {
    recent_steps_us_.reserve(kRecentSteps);
}

void Histories::clear() {
    for (Series& s : force_magnitude) s.clear();
    force_x.clear();
    force_y.clear();
    force_z.clear();
    recent_steps_us_.clear();
    recent_next_ = 0;
    bucket_end_s_ = -1.0;
    started_ = false;
}

void Histories::close_plot_point() {
    for (std::uint32_t i = 0; i < kMaxTools; ++i) {
        force_magnitude[i].push(bucket_max_[i]);
        bucket_max_[i] = 0.0f;
    }
    force_x.push(bucket_force_[0]);
    force_y.push(bucket_force_[1]);
    force_z.push(bucket_force_[2]);
    bucket_force_[0] = bucket_force_[1] = bucket_force_[2] = 0.0f;
}

void Histories::add_step(const StepSample& step) {
    if (bucket_end_s_ < 0.0) bucket_end_s_ = step.time_s + kPlotPointS;
    while (step.time_s > bucket_end_s_ + 1e-12) {
        close_plot_point();
        bucket_end_s_ += kPlotPointS;
    }
    bool touching = false;
    for (std::uint32_t i = 0; i < kMaxTools; ++i) {
        const float* f = step.force_N[i];
        const float magnitude = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        if (magnitude > bucket_max_[i]) {
            bucket_max_[i] = magnitude;
            if (i == plotted_tool) std::copy(f, f + 3, bucket_force_);
        }
        if (magnitude > 0.0f) touching = true;
        largest_force_N = std::max(largest_force_N, static_cast<double>(magnitude));
    }
    ++samples;
    if (touching) {
        ++nonzero_samples;
        if (first_contact_time_s < 0.0) first_contact_time_s = step.time_s;
    }
    if (recent_steps_us_.size() < kRecentSteps)
        recent_steps_us_.push_back(step.step_us);
    else
        recent_steps_us_[recent_next_] = step.step_us;
    recent_next_ = (recent_next_ + 1) % kRecentSteps;
}

void Histories::add(const FrameState& frame) {
    for (const StepSample& step : frame.new_steps) add_step(step);
    if (!recent_steps_us_.empty()) {
        sorted_steps_us_.assign(recent_steps_us_.begin(), recent_steps_us_.end());
        const auto middle = sorted_steps_us_.begin() + static_cast<long>(sorted_steps_us_.size() / 2);
        std::nth_element(sorted_steps_us_.begin(), middle, sorted_steps_us_.end());
        step_median_us = *middle;
        step_max_us = *std::max_element(recent_steps_us_.begin(), recent_steps_us_.end());
    }

    const auto now = Clock::now();
    if (!started_) {
        started_ = true;
        window_start_ = last_frame_ = now;
        window_time_s_ = frame.time_s;
        window_frames_ = 0;
        window_skin_ms_ = 0.0;
        window_steps_ = frame.stats.steps;
        std::copy(frame.effects, frame.effects + ENT_EFFECT_COUNT, window_effects_);
        return;
    }
    ++window_frames_;
    window_skin_ms_ += frame.skin_update_ms;
    last_frame_ = now;
    const double wall_s = std::chrono::duration<double>(now - window_start_).count();
    if (wall_s < kWindowS) return;
    frame_rate_hz = window_frames_ / wall_s;
    real_time_factor = (frame.time_s - window_time_s_) / wall_s;
    skin_update_ms = window_skin_ms_ / window_frames_;
    // Per effect: its time over the steps of the window, both from the snapshot.
    const std::uint64_t steps = frame.stats.steps - window_steps_;
    for (int e = 0; e < ENT_EFFECT_COUNT; ++e) {
        const ent_effect_stats& current = frame.effects[e];
        effects[e].enabled = current.enabled != 0;
        effects[e].calls = current.calls;
        if (steps > 0)
            effects[e].us_per_step = 1e-3 * static_cast<double>(current.total_time_ns - window_effects_[e].total_time_ns) /
                                     static_cast<double>(steps);
        window_effects_[e] = current;
    }
    window_steps_ = frame.stats.steps;
    window_start_ = now;
    window_time_s_ = frame.time_s;
    window_frames_ = 0;
    window_skin_ms_ = 0.0;
}

}  // namespace viewer
