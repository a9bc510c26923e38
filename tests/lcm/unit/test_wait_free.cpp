// SPDX-License-Identifier: Apache-2.0
// The exchanges between the tick and the bridge's other threads: the SPSC queue and the
// "newest value wins" mailbox, alone and between two threads (run under ThreadSanitizer by
// scripts/test), and the publisher's wakeup.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>

#include "lcm/latest_mailbox.h"
#include "lcm/spsc_queue.h"
#include "lcm/wakeup.h"

namespace enteron::lcm {
namespace {

TEST(SpscQueue, HoldsItsCapacityInOrderThenRefuses) {
    SpscQueue<int> queue(5);  // rounded up to 8
    ASSERT_EQ(queue.capacity(), 8u);
    EXPECT_TRUE(queue.empty());
    for (int i = 0; i < 8; ++i) EXPECT_TRUE(queue.push(i));
    EXPECT_FALSE(queue.push(8)) << "a full queue refuses, it never overwrites";
    int value = -1;
    for (int i = 0; i < 8; ++i) {
        ASSERT_TRUE(queue.pop(value));
        EXPECT_EQ(value, i);
    }
    EXPECT_FALSE(queue.pop(value));
    EXPECT_TRUE(queue.empty());
}

TEST(SpscQueue, ClaimAndFrontWorkInPlace) {
    SpscQueue<int> queue(2);
    int* slot = queue.claim();
    ASSERT_NE(slot, nullptr);
    *slot = 42;
    EXPECT_TRUE(queue.empty()) << "nothing is visible before commit";
    queue.commit();
    const int* front = queue.front();
    ASSERT_NE(front, nullptr);
    EXPECT_EQ(*front, 42);
    queue.release();
    EXPECT_EQ(queue.front(), nullptr);
}

// A producer and a consumer at full speed: every item the producer managed to push arrives,
// once, in order; what it could not push it counts as dropped.
TEST(SpscQueue, TwoThreadsLoseNothingTheyDoNotCount) {
    constexpr uint64_t kItems = 2000000;
    SpscQueue<uint64_t> queue(64);
    std::atomic<bool> done{false};
    uint64_t dropped = 0;
    std::thread producer([&] {
        for (uint64_t i = 1; i <= kItems; ++i)
            if (!queue.push(i)) ++dropped;
        done.store(true);
    });
    uint64_t received = 0, last = 0;
    bool ordered = true;
    for (;;) {
        uint64_t value;
        if (queue.pop(value)) {
            ordered = ordered && value > last;
            last = value;
            ++received;
        } else if (done.load()) {
            if (!queue.pop(value)) break;
            ordered = ordered && value > last;
            last = value;
            ++received;
        }
    }
    producer.join();
    EXPECT_TRUE(ordered);
    EXPECT_EQ(received + dropped, kItems);
    EXPECT_GT(received, 0u);
}

TEST(LatestMailbox, TheReaderGetsTheNewestAndKnowsWhatWasCoalesced) {
    LatestMailbox<int> mailbox(0);
    EXPECT_FALSE(mailbox.take()) << "nothing written yet";
    EXPECT_FALSE(mailbox.write(1)) << "the first value replaces nothing unread";
    EXPECT_TRUE(mailbox.write(2)) << "1 was never taken: coalesced";
    ASSERT_TRUE(mailbox.take());
    EXPECT_EQ(mailbox.front(), 2);
    EXPECT_FALSE(mailbox.take()) << "nothing new since";
    EXPECT_EQ(mailbox.front(), 2) << "front stays until something new comes";
    EXPECT_FALSE(mailbox.write(3));
    ASSERT_TRUE(mailbox.take());
    EXPECT_EQ(mailbox.front(), 3);
}

// A value the reader could see half-written would have mismatched halves.
struct Pair {
    uint64_t a = 0;
    uint64_t padding[6] = {};
    uint64_t b = 0;
};

TEST(LatestMailbox, TwoThreadsNeverSeeATornOrOlderValue) {
    LatestMailbox<Pair> mailbox;
    std::atomic<bool> done{false};
    std::thread writer([&] {
        for (uint64_t i = 1; i <= 2000000; ++i) {
            Pair& back = mailbox.back();
            back.a = i;
            back.b = ~i;
            mailbox.publish();
        }
        done.store(true);
    });
    uint64_t last = 0, taken = 0;
    bool whole = true, newer = true;
    for (;;) {
        const bool finished = done.load();  // read before the take: the last value is then there
        if (mailbox.take()) {
            const Pair& value = mailbox.front();
            whole = whole && value.b == ~value.a;
            newer = newer && value.a > last;
            last = value.a;
            ++taken;
        } else if (finished) {
            break;
        }
    }
    writer.join();
    EXPECT_TRUE(whole);
    EXPECT_TRUE(newer);
    EXPECT_GT(taken, 0u);
}

TEST(Wakeup, NotifyWakesAWaiterAndWorkAlreadyThereIsNotSleptOn) {
    Wakeup wakeup;
    std::atomic<int> work{0};
    // Work already there: wait returns without sleeping for its (long) timeout.
    work.store(1);
    const auto start = std::chrono::steady_clock::now();
    wakeup.wait(10'000'000'000, [&] { return work.load() > 0; });
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    // A waiter with no work wakes on notify (a 10 s timeout would fail the ctest timeout).
    work.store(0);
    std::atomic<bool> woke{false};
    std::thread waiter([&] {
        while (work.load() == 0) wakeup.wait(10'000'000'000, [&] { return work.load() > 0; });
        woke.store(true);
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    work.store(1);
    wakeup.notify();
    waiter.join();
    EXPECT_TRUE(woke.load());
}

}  // namespace
}  // namespace enteron::lcm
