// SPDX-License-Identifier: Apache-2.0
// The calls in flight on a handle (a scene, a skin), and the destroy that races with them.
//
// A C API cannot make a call begun after the destroy safe (the handle may be gone by then),
// but it can make a destroy that races with calls already running on other threads harmless:
// each call counts itself in as it starts and out as it returns; the destroy takes away the
// owner's count. Whoever brings the count to zero tears the object down: the destroy itself
// when no call is in flight, else the last call in flight as it returns (on its thread, so
// the memory goes then). A call that starts after the destroy while the handle still exists
// (a skin holds its scene's handle, or a call is still in flight) finds the object
// destroyed (the count at zero, or the destroyed flag set) and fails with a status without
// touching it.
//
// Entering and leaving are one atomic read-modify-write each on the handle: no lock, no
// system call, no allocation, so the step keeps its promises (tests/no_alloc).
#pragma once

#include <atomic>
#include <cstdint>

namespace enteron::capi {

class CallsInFlight {
public:
    // Counts a call in; false once the object was destroyed (the call must not touch it),
    // also while calls begun before the destroy still run.
    bool enter() noexcept {
        uint32_t users = users_.load(std::memory_order_relaxed);
        do {
            if (users == 0 || destroyed_.load(std::memory_order_relaxed)) return false;
        } while (!users_.compare_exchange_weak(users, users + 1, std::memory_order_acquire, std::memory_order_relaxed));
        return true;
    }

    // Counts a call out; true when it was the last user after the destroy: the caller tears
    // the object down (acquire: it sees everything the other calls did).
    [[nodiscard]] bool leave() noexcept { return users_.fetch_sub(1, std::memory_order_acq_rel) == 1; }

    // The owner's destroy; true when no call is in flight: the caller tears down now. A
    // second destroy while the handle still exists changes nothing and returns false.
    [[nodiscard]] bool destroy() noexcept {
        if (destroyed_.exchange(true, std::memory_order_relaxed)) return false;
        return leave();
    }

private:
    std::atomic<uint32_t> users_{1};  // the owner until the destroy, plus one per call in flight
    std::atomic<bool> destroyed_{false};
};

}  // namespace enteron::capi
