// SPDX-License-Identifier: Apache-2.0
// The calls in flight on a C handle and the destroy that races with them
// (lib/capi/calls_in_flight.h): exactly one party tears the object down, the destroy when no
// call runs, else the last call as it returns; a call that starts after the destroy is
// refused; a second destroy changes nothing. With threads: whatever the interleaving, one
// teardown, after every call that entered has left.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "capi/calls_in_flight.h"

namespace enteron::capi {
namespace {

TEST(CallsInFlight, WithoutCallsTheDestroyTearsDownAtOnce) {
    CallsInFlight calls;
    EXPECT_TRUE(calls.destroy());
    EXPECT_FALSE(calls.enter()) << "a call after the destroy is refused";
}

TEST(CallsInFlight, WithACallInFlightTheLastCallTearsDown) {
    CallsInFlight calls;
    ASSERT_TRUE(calls.enter());
    ASSERT_TRUE(calls.enter());
    EXPECT_FALSE(calls.destroy()) << "two calls run: not now";
    EXPECT_FALSE(calls.enter()) << "refused once destroyed, although calls still run";
    EXPECT_FALSE(calls.leave());
    EXPECT_TRUE(calls.leave()) << "the last call out tears down";
}

TEST(CallsInFlight, ASecondDestroyChangesNothing) {
    CallsInFlight calls;
    ASSERT_TRUE(calls.enter());
    EXPECT_FALSE(calls.destroy());
    EXPECT_FALSE(calls.destroy()) << "must not take a second count away";
    EXPECT_TRUE(calls.leave());
}

TEST(CallsInFlight, CallsLeavingWithoutADestroyNeverTearDown) {
    CallsInFlight calls;
    for (int i = 0; i < 100; ++i) {
        ASSERT_TRUE(calls.enter());
        ASSERT_FALSE(calls.leave());
    }
    EXPECT_TRUE(calls.destroy());
}

// Four threads call in and out while the main thread destroys: over many rounds, exactly
// one teardown each round, and no call inside the object after it.
TEST(CallsInFlight, ARacingDestroyTearsDownOnceAfterTheLastCall) {
    for (int round = 0; round < 200; ++round) {
        CallsInFlight calls;
        std::atomic<int> teardowns{0}, inside{0}, inside_at_teardown{0};
        const auto teardown = [&] {
            teardowns.fetch_add(1);
            inside_at_teardown.fetch_add(inside.load());
        };
        std::vector<std::thread> threads;
        for (int t = 0; t < 4; ++t)
            threads.emplace_back([&] {
                for (int k = 0; k < 200; ++k) {
                    if (!calls.enter()) return;
                    inside.fetch_add(1);
                    inside.fetch_sub(1);
                    if (calls.leave()) teardown();
                }
            });
        std::this_thread::yield();
        if (calls.destroy()) teardown();
        for (std::thread& thread : threads) thread.join();
        ASSERT_EQ(teardowns.load(), 1) << "round " << round;
        ASSERT_EQ(inside_at_teardown.load(), 0) << "round " << round;
    }
}

}  // namespace
}  // namespace enteron::capi
