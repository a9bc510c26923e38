// SPDX-License-Identifier: Apache-2.0
// "Newest value wins" between one writer thread and one reader thread: a triple buffer.
// The writer fills its own slot and swaps it with the middle one; the reader swaps the
// middle one with its own when it holds something new. Neither side ever waits, locks or
// allocates, and the reader never sees a half-written value. Used for each tool's newest
// command (receive thread -> tick) and for the tick's summary (tick -> report thread).
#pragma once

#include <atomic>
#include <cstdint>

namespace enteron::lcm {

template <class T>
class LatestMailbox {
public:
    LatestMailbox() = default;
    // Every slot starts as a copy of `initial` (so that slots holding buffers are sized once).
    explicit LatestMailbox(const T& initial) : slots_{initial, initial, initial} {}

    // Writer: the slot to fill, then publish(). Returns true when the value it replaces in
    // the middle was never taken by the reader (a coalesced value).
    T& back() { return slots_[back_]; }
    bool publish() {
        const uint8_t previous = middle_.exchange(static_cast<uint8_t>(back_ | kFresh), std::memory_order_acq_rel);
        back_ = previous & kIndex;
        return (previous & kFresh) != 0;
    }
    bool write(const T& value) {
        back() = value;
        return publish();
    }

    // Reader: true and `front()` updated when the writer published something since the
    // last take; false (front() unchanged) otherwise.
    bool take() {
        if ((middle_.load(std::memory_order_relaxed) & kFresh) == 0) return false;
        const uint8_t previous = middle_.exchange(front_, std::memory_order_acq_rel);
        front_ = previous & kIndex;
        return true;
    }
    const T& front() const { return slots_[front_]; }

private:
    static constexpr uint8_t kIndex = 3;
    static constexpr uint8_t kFresh = 4;
    T slots_[3]{};
    uint8_t back_ = 0;                   // the writer's slot
    std::atomic<uint8_t> middle_{1};     // the exchanged slot and its fresh bit
    uint8_t front_ = 2;                  // the reader's slot
};

}  // namespace enteron::lcm
