// SPDX-License-Identifier: Apache-2.0
// SampleRing<T, N>: a wait-free single-producer single-consumer queue of N slots. The
// physics thread pushes one sample per step (the force on each tool, the step time); the
// render thread drains them all once a frame, so the plots see every step, not one in
// sixteen. When the render thread falls N samples behind (a stall), new samples are
// dropped and counted rather than making the physics thread wait.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace viewer {

template <class T, std::size_t N>
class SampleRing {
public:
    // Producer thread. False (and one more drop counted) when the ring is full.
    bool push(const T& sample) {
        const std::uint64_t head = head_.load(std::memory_order_relaxed);
        if (head - tail_.load(std::memory_order_acquire) == N) {
            dropped_.fetch_add(1, std::memory_order_relaxed);
            return false;
        }
        slots_[head % N] = sample;
        head_.store(head + 1, std::memory_order_release);
        return true;
    }

    // Consumer thread: calls consume(sample) for every sample pushed since the last drain,
    // oldest first.
    template <class Consume>
    void drain(Consume&& consume) {
        std::uint64_t tail = tail_.load(std::memory_order_relaxed);
        const std::uint64_t head = head_.load(std::memory_order_acquire);
        for (; tail != head; ++tail) consume(slots_[tail % N]);
        tail_.store(tail, std::memory_order_release);
    }

    // Samples dropped so far because the consumer was behind (any thread).
    std::uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

private:
    std::array<T, N> slots_{};
    std::atomic<std::uint64_t> head_{0};  // next slot the producer writes
    std::atomic<std::uint64_t> tail_{0};  // next slot the consumer reads
    std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace viewer
