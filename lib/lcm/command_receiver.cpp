// SPDX-License-Identifier: Apache-2.0
#include "lcm/command_receiver.h"

#include <lcmtypes/enteron_tool_command_t.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>

#include "lcm/message_check.h"

namespace enteron::lcm {

namespace {

// Beyond this distance from the scene's origin (once mapped) a position is a mistake.
constexpr double kLargestPosition_m = 1000.0;

bool all_finite(const double* values, int count) {
    for (int i = 0; i < count; ++i)
        if (!std::isfinite(values[i])) return false;
    return true;
}

Rejection rejected_as(Rejection reason, char* detail, std::size_t detail_size, const char* text) {
    if (detail != nullptr && detail_size > 0) std::snprintf(detail, detail_size, "%s", text);
    return reason;
}

int64_t saturating_add(int64_t a, int64_t b) {
    return a > std::numeric_limits<int64_t>::max() - b ? std::numeric_limits<int64_t>::max() : a + b;
}

}  // namespace

CommandReceiver::CommandReceiver(std::size_t tool_count, const WorkspaceMapping& mapping, int64_t watchdog_ns,
                                 BridgeCounters& counters, HostCallbacks& log)
    : mapping_(mapping),
      watchdog_ns_(watchdog_ns),
      counters_(counters),
      log_(log),
      mailboxes_(tool_count),
      sequences_(tool_count),
      last_rejections_(std::make_unique<LastRejection[]>(tool_count)) {}

Rejection CommandReceiver::check(const void* bytes, std::size_t size, AcceptedCommand& accepted, int32_t& tool,
                                 char* detail, std::size_t detail_size) const {
    char text[192];
    switch (check_message(ENT_LCM_TOOL_COMMAND, bytes, size, text, sizeof text)) {
        case MessageFault::none: break;
        case MessageFault::size: return rejected_as(Rejection::size, detail, detail_size, text);
        default: return rejected_as(Rejection::fingerprint, detail, detail_size, text);
    }
    enteron_tool_command_t command;
    if (enteron_tool_command_t_decode(bytes, 0, static_cast<int>(size), &command) < 0)
        return rejected_as(Rejection::size, detail, detail_size, "tool_command_t does not decode");
    tool = command.tool;  // the tool it is for, whether accepted or not

    if (!all_finite(command.position_m, 3) || !all_finite(command.orientation_wxyz, 4) ||
        !all_finite(command.linear_velocity_m_per_s, 3)) {
        std::snprintf(text, sizeof text, "tool %d seq %" PRId64 ": a number is not finite", command.tool, command.seq);
        return rejected_as(Rejection::not_finite, detail, detail_size, text);
    }
    // Scaled by its largest component first, so that neither tiny nor huge components
    // overflow or underflow the norm.
    const Eigen::Vector4d q(command.orientation_wxyz[0], command.orientation_wxyz[1], command.orientation_wxyz[2],
                            command.orientation_wxyz[3]);
    const double largest = q.cwiseAbs().maxCoeff();
    if (largest == 0.0 || (q / largest).norm() * largest < 1e-6) {
        std::snprintf(text, sizeof text, "tool %d seq %" PRId64 ": the orientation quaternion is zero", command.tool,
                      command.seq);
        return rejected_as(Rejection::zero_quaternion, detail, detail_size, text);
    }
    if (command.tool < 0 || static_cast<std::size_t>(command.tool) >= mailboxes_.size()) {
        std::snprintf(text, sizeof text, "seq %" PRId64 ": tool %d does not exist (the scene has %zu)", command.seq,
                      command.tool, mailboxes_.size());
        return rejected_as(Rejection::unknown_tool, detail, detail_size, text);
    }
    if ((command.grasp != 0 && command.grasp != 1) || (command.force_enable != 0 && command.force_enable != 1)) {
        std::snprintf(text, sizeof text, "tool %d seq %" PRId64 ": grasp and force_enable must be 0 or 1, got %d and %d",
                      command.tool, command.seq, command.grasp, command.force_enable);
        return rejected_as(Rejection::out_of_range, detail, detail_size, text);
    }
    const Eigen::Vector4d unit = q / largest;
    const Pose pose = mapping_.to_scene(
        Eigen::Vector3d(command.position_m[0], command.position_m[1], command.position_m[2]),
        Eigen::Quaterniond(unit[0], unit[1], unit[2], unit[3]));
    if (!pose.position.allFinite() || pose.position.cwiseAbs().maxCoeff() > kLargestPosition_m) {
        std::snprintf(text, sizeof text, "tool %d seq %" PRId64 ": position (%g, %g, %g) lies beyond %g m once mapped",
                      command.tool, command.seq, command.position_m[0], command.position_m[1], command.position_m[2],
                      kLargestPosition_m);
        return rejected_as(Rejection::out_of_range, detail, detail_size, text);
    }
    accepted.seq = command.seq;
    accepted.utime = command.utime;
    accepted.scene_pose = pose;
    accepted.grasp = command.grasp == 1;
    accepted.force_enable = command.force_enable == 1;
    return Rejection::none;
}

Rejection CommandReceiver::feed(const void* bytes, std::size_t size, int64_t received_ns, char* detail,
                                std::size_t detail_size) {
    std::lock_guard<std::mutex> lock(mutex_);
    BridgeCounters::add(counters_.commands_received);
    AcceptedCommand accepted;
    accepted.received_ns = received_ns;
    int32_t tool = -1;
    char text[256];
    Rejection reason = check(bytes, size, accepted, tool, text, sizeof text);
    if (reason == Rejection::none) {
        Sequence& sequence = sequences_[static_cast<std::size_t>(tool)];
        const bool silent_long_enough = received_ns - sequence.last_accepted_ns > watchdog_ns_;
        if (sequence.started && accepted.seq <= sequence.last_seq && !silent_long_enough) {
            std::snprintf(text, sizeof text, "tool %d: seq %" PRId64 " does not follow %" PRId64, tool, accepted.seq,
                          sequence.last_seq);
            reason = Rejection::sequence;
        } else {
            if (sequence.started && accepted.seq <= sequence.last_seq)
                log_.log(LogLevel::info, "enteron_lcm: tool %d: a new command sequence starts at seq %" PRId64
                         " after %.0f ms without commands", tool, accepted.seq,
                         1e-6 * static_cast<double>(received_ns - sequence.last_accepted_ns));
            else if (sequence.started && accepted.seq - 1 > sequence.last_seq) {  // seq > last_seq here: no overflow
                BridgeCounters::add(counters_.sequence_gaps);
                const uint64_t skipped = static_cast<uint64_t>(accepted.seq) - static_cast<uint64_t>(sequence.last_seq) - 1;
                const int64_t missed = skipped > static_cast<uint64_t>(std::numeric_limits<int64_t>::max())
                                           ? std::numeric_limits<int64_t>::max()
                                           : static_cast<int64_t>(skipped);
                counters_.commands_missed.store(saturating_add(BridgeCounters::get(counters_.commands_missed), missed),
                                                std::memory_order_relaxed);
            }
            sequence.started = true;
            sequence.last_seq = accepted.seq;
            sequence.last_accepted_ns = received_ns;
            BridgeCounters::add(counters_.commands_accepted);
            if (mailboxes_[static_cast<std::size_t>(tool)].write(accepted))
                BridgeCounters::add(counters_.commands_coalesced);
            return Rejection::none;
        }
    }
    reject(reason, text);
    note(reason, tool, received_ns);
    if (detail != nullptr && detail_size > 0) std::snprintf(detail, detail_size, "%s", text);
    return reason;
}

void CommandReceiver::note(Rejection reason, int32_t tool, int64_t received_ns) {
    const bool named = tool >= 0 && static_cast<std::size_t>(tool) < mailboxes_.size();
    for (std::size_t t = 0; t < mailboxes_.size(); ++t) {
        if (named && t != static_cast<std::size_t>(tool)) continue;
        last_rejections_[t].received_ns.store(received_ns, std::memory_order_relaxed);
        last_rejections_[t].reason.store(static_cast<int>(reason), std::memory_order_release);
    }
}

Rejection CommandReceiver::recent_rejection(std::size_t tool, int64_t now_ns, int64_t window_ns) const {
    const LastRejection& last = last_rejections_[tool];
    const auto reason = static_cast<Rejection>(last.reason.load(std::memory_order_acquire));
    if (reason == Rejection::none) return reason;
    return now_ns - last.received_ns.load(std::memory_order_relaxed) <= window_ns ? reason : Rejection::none;
}

void CommandReceiver::reject(Rejection reason, const char* detail) {
    const int index = static_cast<int>(reason);
    BridgeCounters::add(counters_.rejected[index]);
    if (!logged_[index]) {
        logged_[index] = true;
        log_.log(LogLevel::warning, "enteron_lcm: rejected a command (%s): %s", rejection_name(reason), detail);
    } else {
        ++unlogged_[index];
    }
}

void CommandReceiver::log_summary(double seconds) {
    std::lock_guard<std::mutex> lock(mutex_);
    char line[400];
    int length = 0;
    int64_t total = 0;
    for (int i = 0; i < kRejectionCount; ++i) {
        if (unlogged_[i] == 0) continue;
        total += unlogged_[i];
        length += std::snprintf(line + length, sizeof line - static_cast<std::size_t>(length), "%s%" PRId64 " %s",
                                length == 0 ? "" : ", ", unlogged_[i], rejection_name(static_cast<Rejection>(i)));
        unlogged_[i] = 0;
        if (length >= static_cast<int>(sizeof line)) break;
    }
    if (total > 0)
        log_.log(LogLevel::warning, "enteron_lcm: rejected %" PRId64 " more commands in the last %.1f s: %s", total,
                 seconds, line);
}

}  // namespace enteron::lcm
