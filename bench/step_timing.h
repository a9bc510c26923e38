// SPDX-License-Identifier: Apache-2.0
// Per-step wall-time samples and their summary, shared by the benchmarks and the peers:
// a 1 kHz haptic loop cares about the median and the slow steps, not the mean.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

namespace enteron::bench {

// Nearest-rank quantile of sorted samples, q in (0, 1]; samples must not be empty.
inline double quantile(const std::vector<double>& sorted, double q) {
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
    return sorted[std::min(sorted.size(), std::max<std::size_t>(rank, 1)) - 1];
}

struct StepTimeSummary {
    double median_us = 0.0;
    double p99_us = 0.0;
    double max_us = 0.0;
};

// Sorts the samples (us) and summarises them; all zero when there are none.
inline StepTimeSummary summarize(std::vector<double>& samples_us) {
    StepTimeSummary summary;
    if (samples_us.empty()) return summary;
    std::sort(samples_us.begin(), samples_us.end());
    summary.median_us = quantile(samples_us, 0.5);
    summary.p99_us = quantile(samples_us, 0.99);
    summary.max_us = samples_us.back();
    return summary;
}

// Runs step() timed on its own, appends the sample (us) and reports it to a Google
// Benchmark state as the iteration's manual time. Returns what step() returns.
template <class State, class Step>
auto timed_iteration(State& state, std::vector<double>& samples_us, Step&& step) {
    const auto start = std::chrono::steady_clock::now();
    auto result = step();
    const auto stop = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(stop - start).count();
    state.SetIterationTime(seconds);
    samples_us.push_back(seconds * 1e6);
    return result;
}

}  // namespace enteron::bench
