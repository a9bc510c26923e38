// SPDX-License-Identifier: Apache-2.0
// The receiving side of the bridge: every message on ENTERON_TOOL_COMMAND (or fed in by
// ent_lcm_bridge_feed_command) is checked here, on the receive thread, never on the tick:
// exact size, fingerprint, finite values, non-zero quaternion, existing tool, 0/1 levels
// and a position within 1 km once mapped, then a seq larger than the tool's last one. A
// rejected command is counted by reason and logged (the first of each reason at once,
// then a sum once a second), never applied. An accepted one, mapped into the scene, goes
// into its tool's mailbox, where the next tick takes the newest.
//
// A sender that restarts counts seq from the beginning again: after the watchdog time
// without any accepted command for a tool, the next one starts a new sequence. While
// another sender keeps the sequence alive, the restarted one is rejected: the last
// rejection of each tool is kept for the tick, whose feedback says so (rejection_status),
// so that a device locked out can tell.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "lcm/bridge_counters.h"
#include "lcm/host_callbacks.h"
#include "lcm/latest_mailbox.h"
#include "lcm/tool_safety.h"
#include "lcm/workspace_mapping.h"

namespace enteron::lcm {

// The tool_feedback_t status of a rejection: STATUS_COMMANDS_REJECTED and the reason
// (REJECTED_* = the Rejection's value + 1) in bits 8-15; 0 for Rejection::none.
inline int32_t rejection_status(Rejection reason) {
    if (reason == Rejection::none) return 0;
    return kCommandsRejected | ((static_cast<int32_t>(reason) + 1) << 8);
}

class CommandReceiver {
public:
    CommandReceiver(std::size_t tool_count, const WorkspaceMapping& mapping, int64_t watchdog_ns,
                    BridgeCounters& counters, HostCallbacks& log);

    // Any thread (serialised here). Returns the reason of a rejection (Rejection::none when
    // accepted); `detail` (may be null) receives a line saying why.
    Rejection feed(const void* bytes, std::size_t size, int64_t received_ns, char* detail, std::size_t detail_size);

    // The tick's side: tool t's mailbox (take() the newest command).
    LatestMailbox<AcceptedCommand>& mailbox(std::size_t tool) { return mailboxes_[tool]; }

    // Report thread, once a second: one line summing the rejections not logged one by one.
    void log_summary(double seconds);

    // The tick's side: why the last command for `tool` was rejected (or the last one that
    // named no tool the bridge could read), if that came within window_ns before now_ns;
    // else Rejection::none. Never waits.
    Rejection recent_rejection(std::size_t tool, int64_t now_ns, int64_t window_ns) const;

private:
    Rejection check(const void* bytes, std::size_t size, AcceptedCommand& accepted, int32_t& tool, char* detail,
                    std::size_t detail_size) const;
    void reject(Rejection reason, const char* detail);
    // Keeps a rejection for recent_rejection: for `tool`, or for every tool when it names none.
    void note(Rejection reason, int32_t tool, int64_t received_ns);

    struct Sequence {
        bool started = false;
        int64_t last_seq = 0;
        int64_t last_accepted_ns = 0;
    };

    const WorkspaceMapping& mapping_;
    const int64_t watchdog_ns_;
    BridgeCounters& counters_;
    HostCallbacks& log_;
    std::vector<LatestMailbox<AcceptedCommand>> mailboxes_;
    std::mutex mutex_;  // the receive thread and feed_command callers; never the tick
    std::vector<Sequence> sequences_;
    bool logged_[kRejectionCount] = {};     // the first rejection of each reason was logged
    int64_t unlogged_[kRejectionCount] = {};  // rejections since, not logged one by one
    // Per tool, the last rejection: written under mutex_, read by the tick without it (a
    // reason and a time read a moment apart is still a recent rejection).
    struct LastRejection {
        std::atomic<int> reason{static_cast<int>(Rejection::none)};
        std::atomic<int64_t> received_ns{0};
    };
    std::unique_ptr<LastRejection[]> last_rejections_;
};

}  // namespace enteron::lcm
