// SPDX-License-Identifier: Apache-2.0
// What a caller tells one tool between steps, from any thread: the pose to reach at the end
// of the next step, and a grasp or a release. The stepping thread takes both at the start
// of each step. A haptic thread at 1 kHz posts poses while the physics thread steps, and
// neither ever waits for the other.
//
// Posting is wait-free, also from several threads at once: a post takes a ticket (one
// atomic increment) and writes its pose into a slot of a small ring under a per-slot
// sequence number (a seqlock whose writer claims the slot by compare-and-swap, so that two
// posts never write one slot together; its values are atomics stored with release and
// loaded with acquire, so it needs no fence). The last post wins, in the order the posts took
// their tickets: the stepping thread takes the newest complete post and ignores an older
// one that completes later. With fewer than kSlots posts in flight at once (one haptic
// thread and a script, say), a post always finds a slot; a post that finds every slot busy
// with concurrent posts is dropped as if a later one had replaced it.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "collision/tool.h"

namespace enteron::collision {

class ToolMailbox {
public:
    enum class Grasp : uint8_t { none, grasp, release };

    // Any thread, wait-free. pose is validated (a unit quaternion).
    void post_pose(const ToolPose& pose);
    // Any thread, wait-free: the grasp or release to make at the start of the next step.
    void post_grasp(Grasp command);

    // The stepping thread only. The newest pose posted since the last take, if any.
    bool take_pose(ToolPose& pose);
    // The last grasp or release posted since the last take (none if none).
    Grasp take_grasp();

    // The tool was removed (the driving thread marks it; any thread asks): its commands
    // are refused from then on.
    void retire() { retired_.store(true, std::memory_order_release); }
    bool retired() const { return retired_.load(std::memory_order_acquire); }

private:
    static constexpr std::size_t kSlots = 4;
    static constexpr std::size_t kValues = 7;  // position x y z, orientation w x y z
    struct Slot {
        // 0: never written; 2 t - 1: post t is writing; 2 t: post t is complete.
        std::atomic<uint64_t> sequence{0};
        std::array<std::atomic<double>, kValues> values{};
    };

    std::atomic<uint64_t> tickets_{0};
    std::array<Slot, kSlots> slots_;
    std::atomic<Grasp> grasp_{Grasp::none};
    std::atomic<bool> retired_{false};
    uint64_t taken_ = 0;  // the ticket of the last pose taken (stepping thread)
};

}  // namespace enteron::collision
