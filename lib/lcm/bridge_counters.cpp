// SPDX-License-Identifier: Apache-2.0
#include "lcm/bridge_counters.h"

namespace enteron::lcm {

const char* rejection_name(Rejection reason) {
    switch (reason) {
        case Rejection::size: return "size";
        case Rejection::fingerprint: return "fingerprint";
        case Rejection::not_finite: return "not finite";
        case Rejection::zero_quaternion: return "zero quaternion";
        case Rejection::unknown_tool: return "unknown tool";
        case Rejection::out_of_range: return "out of range";
        case Rejection::sequence: return "sequence";
        default: return "accepted";
    }
}

void BridgeCounters::fill(ent_lcm_stats& out) const {
    out.session_id = session_id;
    out.ticks = get(ticks);
    out.sim_time_s = sim_time_s.load(std::memory_order_relaxed);
    out.missed_deadlines = get(missed_deadlines);
    out.commands_received = get(commands_received);
    out.commands_accepted = get(commands_accepted);
    out.commands_coalesced = get(commands_coalesced);
    out.rejected_size = get(rejected[static_cast<int>(Rejection::size)]);
    out.rejected_fingerprint = get(rejected[static_cast<int>(Rejection::fingerprint)]);
    out.rejected_not_finite = get(rejected[static_cast<int>(Rejection::not_finite)]);
    out.rejected_zero_quaternion = get(rejected[static_cast<int>(Rejection::zero_quaternion)]);
    out.rejected_unknown_tool = get(rejected[static_cast<int>(Rejection::unknown_tool)]);
    out.rejected_sequence = get(rejected[static_cast<int>(Rejection::sequence)]);
    out.rejected_out_of_range = get(rejected[static_cast<int>(Rejection::out_of_range)]);
    out.sequence_gaps = get(sequence_gaps);
    out.commands_missed = get(commands_missed);
    out.watchdog_trips = get(watchdog_trips);
    out.step_failures = get(step_failures);
    out.step_us_median = step_us_median.load(std::memory_order_relaxed);
    out.step_us_max = step_us_max.load(std::memory_order_relaxed);
    out.tick_us_max = tick_us_max.load(std::memory_order_relaxed);
    out.feedback_published = get(feedback_published);
    out.feedback_dropped = get(feedback_dropped);
    out.journal_entries = get(journal_entries);
    out.journal_dropped = get(journal_dropped);
    out.log_lines_dropped = get(log_lines_dropped);
}

}  // namespace enteron::lcm
