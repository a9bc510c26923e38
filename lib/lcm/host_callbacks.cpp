// SPDX-License-Identifier: Apache-2.0
#include "lcm/host_callbacks.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace enteron::lcm {

HostCallbacks::HostCallbacks(const ent_callbacks* host, BridgeCounters& counters) : counters_(counters) {
    ent_callbacks_default(&host_);
    // A caller's older, smaller struct is copied only as far as it goes (its struct_size
    // was checked against the released sizes before).
    if (host != nullptr) std::memcpy(&host_, host, std::min<std::size_t>(host->struct_size, sizeof host_));
    host_.struct_size = sizeof host_;
    ent_callbacks_default(&scene_callbacks_);
    scene_callbacks_.user_data = this;
    if (host_.log != nullptr) scene_callbacks_.log = scene_log;
    if (host_.allocate != nullptr && host_.release != nullptr) {
        scene_callbacks_.allocate = scene_allocate;
        scene_callbacks_.release = scene_release;
    }
}

void HostCallbacks::forward(int32_t level, const char* text) {
    if (host_.log == nullptr) return;
    std::lock_guard<std::mutex> lock(mutex_);
    host_.log(host_.user_data, level, text);
}

void HostCallbacks::log(LogLevel level, const char* format, ...) {
    if (host_.log == nullptr) return;
    char line[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    forward(static_cast<int32_t>(level), line);
}

void HostCallbacks::scene_log(void* self, int32_t level, const char* message) {
    auto* callbacks = static_cast<HostCallbacks*>(self);
    if (callbacks->in_tick_.load(std::memory_order_relaxed) && pthread_equal(pthread_self(), callbacks->tick_thread_)) {
        Line* line = callbacks->tick_lines_.claim();
        if (line == nullptr) {
            BridgeCounters::add(callbacks->counters_.log_lines_dropped);
            return;
        }
        line->level = level;
        std::strncpy(line->text, message, sizeof line->text - 1);
        line->text[sizeof line->text - 1] = '\0';
        callbacks->tick_lines_.commit();
        return;
    }
    callbacks->forward(level, message);
}

void* HostCallbacks::scene_allocate(void* self, std::size_t size, std::size_t alignment) {
    const ent_callbacks& host = static_cast<HostCallbacks*>(self)->host_;
    return host.allocate(host.user_data, size, alignment);
}

void HostCallbacks::scene_release(void* self, void* memory, std::size_t size, std::size_t alignment) {
    const ent_callbacks& host = static_cast<HostCallbacks*>(self)->host_;
    host.release(host.user_data, memory, size, alignment);
}

void HostCallbacks::drain() {
    for (const Line* line = tick_lines_.front(); line != nullptr; line = tick_lines_.front()) {
        forward(line->level, line->text);
        tick_lines_.release();
    }
}

}  // namespace enteron::lcm
