// SPDX-License-Identifier: Apache-2.0
// The tools' channels to the caller's threads. In: a mailbox per tool (tool_mailbox.h),
// posted to from any thread and taken by the tools effect at the start of each step. Out:
// each tool's ToolOutput, written by the tools effect at the end of each step and published
// by the scene in its snapshot; and what each tool was added with, fixed from then on.
//
// Tools are added between steps while other threads may be posting: the mailboxes never
// move, and the table that finds them by index is replaced, not changed, when one is added
// (an older table stays valid until the channels are destroyed, for a post that still
// reads it).
#pragma once

#include <atomic>
#include <cstddef>
#include <memory_resource>
#include <vector>

#include "base/memory.h"
#include "collision/tool.h"
#include "collision/tool_mailbox.h"

namespace enteron::collision {

class ToolChannels {
public:
    explicit ToolChannels(std::pmr::memory_resource* memory);
    ToolChannels(const ToolChannels&) = delete;
    ToolChannels& operator=(const ToolChannels&) = delete;

    // Any thread: the number of tools, the mailbox of tool `index` and the settings and pose
    // it was added with (null if there is no such tool).
    std::size_t size() const { return table_.load(std::memory_order_acquire)->size(); }
    ToolMailbox* mailbox(std::size_t index);
    const ToolMailbox* mailbox(std::size_t index) const;
    const ToolConfig* added(std::size_t index) const;
    // Any thread: the tools added and not removed (ToolMailbox::retired).
    std::size_t present() const;

    // The driving thread only. add() makes the channels of one more tool, added as `tool`
    // (allocates), and returns its index; outputs() are the tools' outputs, by index.
    std::size_t add(const ToolConfig& tool);
    std::pmr::vector<ToolOutput>& outputs() { return outputs_; }
    const std::pmr::vector<ToolOutput>& outputs() const { return outputs_; }

private:
    struct Entry {
        ToolMailbox* mailbox;
        const ToolConfig* added;
    };
    using Table = std::pmr::vector<Entry>;

    std::pmr::memory_resource* memory_;
    std::pmr::vector<Owned<ToolMailbox>> mailboxes_;
    std::pmr::vector<Owned<ToolConfig>> added_;
    std::pmr::vector<Owned<Table>> tables_;  // every table published, the current one last
    std::atomic<const Table*> table_;
    std::pmr::vector<ToolOutput> outputs_;
};

}  // namespace enteron::collision
