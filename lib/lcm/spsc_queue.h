// SPDX-License-Identifier: Apache-2.0
// A bounded single-producer single-consumer queue: how the tick hands its feedback, journal
// entries and log lines to the bridge's other threads without waiting for them, without a
// lock and without allocating (Lamport's ring, with acquire/release indices). Both sides are
// wait-free: push fails when the queue is full (the producer counts a drop), pop when it
// is empty.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

namespace enteron::lcm {

// Keeps the two indices on separate cache lines, so that the producer and the consumer do
// not invalidate each other's line on every operation.
inline constexpr std::size_t kCacheLine = 64;

template <class T>
class SpscQueue {
public:
    // Room for `capacity` items, rounded up to a power of two; allocates here, never after.
    explicit SpscQueue(std::size_t capacity) {
        std::size_t size = 2;
        while (size < capacity) size *= 2;
        mask_ = size - 1;
        slots_ = std::make_unique<T[]>(size);
    }

    std::size_t capacity() const { return mask_ + 1; }

    // Producer: the slot the next push fills, or nullptr when the queue is full. Fill it in
    // place, then commit() (no copy of a large item).
    T* claim() {
        const uint64_t tail = tail_.load(std::memory_order_relaxed);
        if (tail - head_cache_ > mask_) {
            head_cache_ = head_.load(std::memory_order_acquire);
            if (tail - head_cache_ > mask_) return nullptr;
        }
        return &slots_[tail & mask_];
    }
    void commit() { tail_.store(tail_.load(std::memory_order_relaxed) + 1, std::memory_order_release); }

    bool push(const T& item) {
        T* slot = claim();
        if (slot == nullptr) return false;
        *slot = item;
        commit();
        return true;
    }

    // Consumer: the oldest item, or nullptr when the queue is empty. Read it in place, then
    // release() it.
    const T* front() {
        const uint64_t head = head_.load(std::memory_order_relaxed);
        if (head == tail_cache_) {
            tail_cache_ = tail_.load(std::memory_order_acquire);
            if (head == tail_cache_) return nullptr;
        }
        return &slots_[head & mask_];
    }
    void release() { head_.store(head_.load(std::memory_order_relaxed) + 1, std::memory_order_release); }

    bool pop(T& item) {
        const T* slot = front();
        if (slot == nullptr) return false;
        item = *slot;
        release();
        return true;
    }

    // Either side: whether the queue looked empty at this moment.
    bool empty() const { return head_.load(std::memory_order_acquire) == tail_.load(std::memory_order_acquire); }

private:
    std::unique_ptr<T[]> slots_;
    std::size_t mask_ = 0;
    alignas(kCacheLine) std::atomic<uint64_t> tail_{0};  // written by the producer
    uint64_t head_cache_ = 0;                             // the producer's last view of head_
    alignas(kCacheLine) std::atomic<uint64_t> head_{0};  // written by the consumer
    uint64_t tail_cache_ = 0;                             // the consumer's last view of tail_
};

}  // namespace enteron::lcm
