// SPDX-License-Identifier: Apache-2.0
#include "collision/tool_channels.h"

namespace enteron::collision {

ToolChannels::ToolChannels(std::pmr::memory_resource* memory)
    : memory_(memory), mailboxes_(memory), added_(memory), tables_(memory), outputs_(memory) {
    tables_.push_back(make_owned<Table>(memory, memory));
    table_.store(tables_.back().get(), std::memory_order_release);
}

ToolMailbox* ToolChannels::mailbox(std::size_t index) {
    const Table& table = *table_.load(std::memory_order_acquire);
    return index < table.size() ? table[index].mailbox : nullptr;
}

const ToolMailbox* ToolChannels::mailbox(std::size_t index) const {
    return const_cast<ToolChannels*>(this)->mailbox(index);
}

const ToolConfig* ToolChannels::added(std::size_t index) const {
    const Table& table = *table_.load(std::memory_order_acquire);
    return index < table.size() ? table[index].added : nullptr;
}

std::size_t ToolChannels::present() const {
    std::size_t count = 0;
    for (const Entry& entry : *table_.load(std::memory_order_acquire)) count += !entry.mailbox->retired();
    return count;
}

std::size_t ToolChannels::add(const ToolConfig& tool) {
    // Everything that can fail is made before anything changes.
    mailboxes_.reserve(mailboxes_.size() + 1);
    added_.reserve(added_.size() + 1);
    tables_.reserve(tables_.size() + 1);
    outputs_.reserve(outputs_.size() + 1);
    Owned<ToolMailbox> mailbox = make_owned<ToolMailbox>(memory_);
    Owned<ToolConfig> added = make_owned<ToolConfig>(memory_, tool);
    Owned<Table> table = make_owned<Table>(memory_, *tables_.back(), memory_);
    table->push_back({mailbox.get(), added.get()});
    mailboxes_.push_back(std::move(mailbox));
    added_.push_back(std::move(added));
    outputs_.emplace_back();
    tables_.push_back(std::move(table));
    table_.store(tables_.back().get(), std::memory_order_release);
    return outputs_.size() - 1;
}

}  // namespace enteron::collision
