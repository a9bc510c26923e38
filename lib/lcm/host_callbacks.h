// SPDX-License-Identifier: Apache-2.0
// The host's callbacks (ent_lcm_bridge_desc.callbacks), shared by the bridge and its
// scene. Log lines go to the host's log callback, one call at a time; lines the scene
// logs during a tick (a rollback of the stability guard) are queued instead and handed
// over by the report thread (drain()), so that the tick never waits on the callback or on
// what it does (printing is a system call). The scene is created with trampolines that
// forward its log lines here and its allocations to the host's allocator.
#pragma once

#include <pthread.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>

#include "base/logger.h"
#include "enteron/enteron.h"
#include "lcm/bridge_counters.h"
#include "lcm/spsc_queue.h"

namespace enteron::lcm {

class HostCallbacks {
public:
    // host may be null (silent, malloc/free).
    HostCallbacks(const ent_callbacks* host, BridgeCounters& counters);
    HostCallbacks(const HostCallbacks&) = delete;
    HostCallbacks& operator=(const HostCallbacks&) = delete;

    // The callbacks to create the scene with (they point back at this object).
    const ent_callbacks& scene_callbacks() const { return scene_callbacks_; }

    // From any thread but the ticking one.
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    void log(LogLevel level, const char* format, ...);

    // The tick marks its span, so lines logged from inside it are queued.
    void enter_tick() {
        tick_thread_ = pthread_self();
        in_tick_.store(true, std::memory_order_relaxed);
    }
    void leave_tick() { in_tick_.store(false, std::memory_order_relaxed); }

    // Report thread: forwards the queued lines.
    void drain();

private:
    struct Line {
        int32_t level = 0;
        char text[256] = {};
    };
    static void scene_log(void* self, int32_t level, const char* message);
    static void* scene_allocate(void* self, std::size_t size, std::size_t alignment);
    static void scene_release(void* self, void* memory, std::size_t size, std::size_t alignment);
    void forward(int32_t level, const char* text);

    ent_callbacks host_{};
    ent_callbacks scene_callbacks_{};
    BridgeCounters& counters_;
    std::mutex mutex_;  // one log call at a time
    SpscQueue<Line> tick_lines_{64};
    std::atomic<bool> in_tick_{false};
    pthread_t tick_thread_{};
};

}  // namespace enteron::lcm
