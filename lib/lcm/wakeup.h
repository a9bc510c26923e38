// SPDX-License-Identifier: Apache-2.0
// Wakes a sleeping consumer thread (the publisher) without the producer ever waiting: the
// producer bumps a counter and, only if the consumer is asleep, makes one futex wake (a
// non-blocking system call); the consumer sleeps on the counter with a timeout, so that a
// missed notify costs at most that timeout.
#pragma once

#include <atomic>
#include <cstdint>

namespace enteron::lcm {

class Wakeup {
public:
    // Producer, after making work visible (e.g. SpscQueue::commit). Any thread.
    void notify();

    // Consumer: sleeps until notify() or timeout_ns, unless `has_work()` is already true.
    // has_work is checked after announcing the sleep, so no notify is lost.
    template <class HasWork>
    void wait(int64_t timeout_ns, HasWork&& has_work) {
        sleeping_.store(true, std::memory_order_seq_cst);
        const uint32_t seen = counter_.load(std::memory_order_seq_cst);
        if (!has_work()) sleep(seen, timeout_ns);
        sleeping_.store(false, std::memory_order_relaxed);
    }

private:
    void sleep(uint32_t seen, int64_t timeout_ns);

    std::atomic<uint32_t> counter_{0};
    std::atomic<bool> sleeping_{false};
};

}  // namespace enteron::lcm
