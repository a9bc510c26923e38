// SPDX-License-Identifier: Apache-2.0
#include "collision/tool_mailbox.h"

namespace enteron::collision {

void ToolMailbox::post_pose(const ToolPose& pose) {
    const uint64_t ticket = tickets_.fetch_add(1, std::memory_order_relaxed) + 1;
    for (std::size_t k = 0; k < kSlots; ++k) {
        Slot& slot = slots_[(ticket + k) % kSlots];
        uint64_t seen = slot.sequence.load(std::memory_order_relaxed);
        // A slot that another post is writing, or that holds a later post, is not ours.
        if (seen % 2 == 1 || seen / 2 > ticket) continue;
        if (!slot.sequence.compare_exchange_strong(seen, 2 * ticket - 1, std::memory_order_relaxed)) continue;
        // Release stores (free on x86): a reader that sees any of these values also sees the
        // claim when it reads the sequence again, and retries (a seqlock without fences,
        // which ThreadSanitizer can follow).
        for (std::size_t c = 0; c < 3; ++c) slot.values[c].store(pose.position[c], std::memory_order_release);
        for (std::size_t c = 0; c < 4; ++c) slot.values[3 + c].store(pose.orientation[c], std::memory_order_release);
        slot.sequence.store(2 * ticket, std::memory_order_release);
        return;
    }
}

void ToolMailbox::post_grasp(Grasp command) { grasp_.store(command, std::memory_order_release); }

bool ToolMailbox::take_pose(ToolPose& pose) {
    // A slot can change under the copy only if newer posts keep claiming it; after a few
    // tries the pose waits for the next step.
    for (std::size_t attempt = 0; attempt <= kSlots; ++attempt) {
        const Slot* newest = nullptr;
        uint64_t newest_sequence = 0;
        for (const Slot& slot : slots_) {
            const uint64_t sequence = slot.sequence.load(std::memory_order_acquire);
            if (sequence % 2 == 0 && sequence / 2 > taken_ && sequence > newest_sequence) {
                newest = &slot;
                newest_sequence = sequence;
            }
        }
        if (newest == nullptr) return false;
        ToolPose copy;
        for (std::size_t c = 0; c < 3; ++c) copy.position[c] = newest->values[c].load(std::memory_order_acquire);
        for (std::size_t c = 0; c < 4; ++c)
            copy.orientation[c] = newest->values[3 + c].load(std::memory_order_acquire);
        if (newest->sequence.load(std::memory_order_relaxed) != newest_sequence) continue;  // overwritten
        taken_ = newest_sequence / 2;
        pose = copy;
        return true;
    }
    return false;
}

ToolMailbox::Grasp ToolMailbox::take_grasp() { return grasp_.exchange(Grasp::none, std::memory_order_acquire); }

}  // namespace enteron::collision
