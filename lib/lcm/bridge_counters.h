// SPDX-License-Identifier: Apache-2.0
// The bridge's counters (ent_lcm_stats, server_status_t): plain atomics that each thread
// adds to (relaxed: they are statistics, read once a second) and any thread reads.
#pragma once

#include <atomic>
#include <cstdint>

#include "enteron/enteron_lcm.h"

namespace enteron::lcm {

// Why a command was rejected, in the order the receive thread checks. In tool_feedback_t's
// status a reason is its value + 1 (REJECTED_*) in bits 8-15.
enum class Rejection : int {
    size,
    fingerprint,
    not_finite,
    zero_quaternion,
    unknown_tool,
    out_of_range,
    sequence,
    count,     // number of reasons
    none = -1  // accepted
};
constexpr int kRejectionCount = static_cast<int>(Rejection::count);
const char* rejection_name(Rejection reason);

struct BridgeCounters {
    int64_t session_id = 0;
    std::atomic<int64_t> ticks{0};
    std::atomic<double> sim_time_s{0.0};
    std::atomic<int64_t> missed_deadlines{0};
    std::atomic<int64_t> commands_received{0};
    std::atomic<int64_t> commands_accepted{0};
    std::atomic<int64_t> commands_coalesced{0};
    std::atomic<int64_t> rejected[kRejectionCount] = {};
    std::atomic<int64_t> sequence_gaps{0};
    std::atomic<int64_t> commands_missed{0};
    std::atomic<int64_t> watchdog_trips{0};
    std::atomic<int64_t> step_failures{0};
    std::atomic<int32_t> step_us_median{0};    // over the last full second (report thread)
    std::atomic<int32_t> step_us_max{0};
    std::atomic<int32_t> tick_us_max{0};
    std::atomic<int64_t> tick_ns_max_window{0};  // largest tick since the report thread last took it
    std::atomic<int64_t> feedback_published{0};
    std::atomic<int64_t> feedback_dropped{0};
    std::atomic<int64_t> journal_entries{0};
    std::atomic<int64_t> journal_dropped{0};
    std::atomic<int64_t> log_lines_dropped{0};

    static void add(std::atomic<int64_t>& counter, int64_t amount = 1) {
        counter.fetch_add(amount, std::memory_order_relaxed);
    }
    static int64_t get(const std::atomic<int64_t>& counter) { return counter.load(std::memory_order_relaxed); }

    // Every field of ent_lcm_stats, whatever struct_size says (the caller copies the prefix).
    void fill(ent_lcm_stats& out) const;
};

}  // namespace enteron::lcm
