// SPDX-License-Identifier: Apache-2.0
// LatestValue<T>: one thread publishes values, another takes the newest; neither ever
// waits for the other. A triple buffer: the writer fills its own slot and swaps it with
// the shared middle slot in one atomic exchange; the reader swaps its slot with the middle
// one only when the middle holds something new. Old values are simply overwritten, which
// is what a pose target or a status wants: the newest one wins.
#pragma once

#include <atomic>

namespace viewer {

template <class T>
class LatestValue {
public:
    // Writer thread: publishes a copy of value.
    void publish(const T& value) {
        slots_[back_] = value;
        back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & kIndex;
    }

    // Reader thread: copies the newest value into out if one was published since the last
    // take, and says so; otherwise leaves out as it was.
    bool take(T& out) {
        if ((middle_.load(std::memory_order_relaxed) & kFresh) == 0) return false;
        front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
        out = slots_[front_];
        return true;
    }

private:
    static constexpr unsigned kIndex = 3;  // the slot index in middle_
    static constexpr unsigned kFresh = 4;  // set by publish, cleared by take

    T slots_[3]{};
    unsigned back_ = 0;   // the writer's slot
    unsigned front_ = 1;  // the reader's slot
    std::atomic<unsigned> middle_{2};
};

}  // namespace viewer
