// The receiving side of the bridge: every message on ENTERON_TOOL_COMMAND (or fed in by
// ent_lcm_bridge_feed_command) is checked here, on the receive thread, never on the tick:
// exact size, fingerprint, finite values, non-zero quaternion, existing tool, 0/1 levels
// and a position within 1 km once mapped, then a seq larger than the tool's last one. A
// rejected command is counted by reason and logged (the first of each reason at once,
// then a sum once a second), never applied. An accepted one, mapped into the scene, goes
// into its tool's mailbox, where the next tick takes the newest.
//
// A sender that restarts counts seq from the beginning again: after the watchdog time
// without any accepted command for a tool, the next one starts a new sequence.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "lcm/bridge_counters.h"
#include "lcm/host_callbacks.h"
#include "lcm/latest_mailbox.h"
#include "lcm/tool_safety.h"
#include "lcm/workspace_mapping.h"

namespace enteron::lcm {

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

private:
    Rejection check(const void* bytes, std::size_t size, AcceptedCommand& accepted, int32_t& tool, char* detail,
                    std::size_t detail_size) const;
    void reject(Rejection reason, const char* detail);

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
};

}  // namespace enteron::lcm
