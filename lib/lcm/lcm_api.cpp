// SPDX-License-Identifier: Apache-2.0
// The C API of libenteron_lcm (include/enteron/enteron_lcm.h): checked calls into the
// Bridge, errors as a status and ent_lcm_last_error().
#include <cstring>
#include <new>
#include <utility>

#include "capi/call_guard.h"
#include "capi/struct_size.h"
#include "lcm/bridge.h"
#include "lcm/clock.h"
#include "lcm/journal_replay.h"
#include "lcm/message_check.h"

using enteron::Error;
using enteron::ErrorCode;
using enteron::lcm::Bridge;
using enteron::capi::require;

struct ent_lcm_bridge {
    Bridge bridge;
};

namespace {

// libenteron_lcm's own per-thread message (ent_lcm_last_error), stored by the call guard
// libenteron uses too (capi/call_guard.h).
thread_local char last_error[1024] = "";

void set_last_error(const char* message) {
    std::strncpy(last_error, message, sizeof last_error - 1);
    last_error[sizeof last_error - 1] = '\0';
}

template <class Body>
ent_status guarded(Body&& body) noexcept {
    return enteron::capi::guarded_with<set_last_error>(std::forward<Body>(body));
}

// The released sizes of the output structs (this is their first release).
constexpr std::size_t kStatsSizes[] = {sizeof(ent_lcm_stats)};

}  // namespace

extern "C" {

ENT_API uint32_t ent_lcm_version(void) { return ENT_VERSION; }

ENT_API const char* ent_lcm_last_error(void) { return last_error; }

ENT_API int64_t ent_lcm_monotonic_ns(void) { return enteron::lcm::monotonic_ns(); }

ENT_API ent_status ent_lcm_bridge_desc_init(ent_lcm_bridge_desc* desc, uint32_t struct_size) {
    return guarded([&] {
        require(desc, "desc");
        enteron::capi::check_struct_size(struct_size, {sizeof(ent_lcm_bridge_desc)}, "ent_lcm_bridge_desc");
        ent_lcm_bridge_desc defaults = enteron::lcm::default_bridge_desc();
        defaults.struct_size = struct_size;
        std::memcpy(desc, &defaults, struct_size);
    });
}

ENT_API ent_status ent_lcm_bridge_create(const ent_lcm_bridge_desc* desc, ent_lcm_bridge** out_bridge) {
    return guarded([&] {
        require(desc, "desc");
        require(out_bridge, "out_bridge");
        enteron::lcm::BridgeSettings settings = enteron::lcm::bridge_settings(*desc);
        *out_bridge = new ent_lcm_bridge{Bridge(std::move(settings))};
    });
}

ENT_API void ent_lcm_bridge_destroy(ent_lcm_bridge* bridge) { delete bridge; }

ENT_API ent_scene* ent_lcm_bridge_scene(ent_lcm_bridge* bridge) {
    return bridge != nullptr ? bridge->bridge.scene() : nullptr;
}

ENT_API ent_status ent_lcm_bridge_lcm(ent_lcm_bridge* bridge, void** out_lcm) {
    return guarded([&] {
        require(bridge, "bridge");
        require(out_lcm, "out_lcm");
        if (bridge->bridge.lcm() == nullptr)
            throw Error(ErrorCode::not_found, "the bridge has no LCM instance (its lcm_url was \"\")");
        *out_lcm = bridge->bridge.lcm();
    });
}

ENT_API ent_status ent_lcm_bridge_tick(ent_lcm_bridge* bridge, int64_t now_ns) {
    if (bridge == nullptr) {
        set_last_error("bridge must not be NULL");
        return ENT_ERROR_INVALID_ARGUMENT;
    }
    if (bridge->bridge.started()) {
        set_last_error("the bridge was started: its own physics thread ticks (ent_lcm_bridge_stop first)");
        return ENT_ERROR_INVALID_ARGUMENT;
    }
    const ent_status status = bridge->bridge.tick(now_ns);
    if (status != ENT_OK) set_last_error("the scene refused a call of the tick (see ent_last_error)");
    return status;
}

ENT_API void ent_lcm_bridge_notify(ent_lcm_bridge* bridge) {
    if (bridge != nullptr) bridge->bridge.notify();
}

ENT_API ent_status ent_lcm_bridge_start(ent_lcm_bridge* bridge) {
    return guarded([&] {
        require(bridge, "bridge");
        bridge->bridge.start();
    });
}

ENT_API ent_status ent_lcm_bridge_stop(ent_lcm_bridge* bridge) {
    return guarded([&] {
        require(bridge, "bridge");
        bridge->bridge.stop();
    });
}

ENT_API ent_status ent_lcm_bridge_feed_command(ent_lcm_bridge* bridge, const void* bytes, size_t size,
                                              int64_t received_ns) {
    return guarded([&] {
        require(bridge, "bridge");
        if (bytes == nullptr && size > 0) throw Error(ErrorCode::invalid_argument, "bytes must not be NULL");
        static const unsigned char nothing = 0;
        char detail[256] = "";
        const enteron::lcm::Rejection reason =
            bridge->bridge.feed(bytes != nullptr ? bytes : &nothing, size, received_ns, detail, sizeof detail);
        if (reason != enteron::lcm::Rejection::none)
            throw Error(ErrorCode::invalid_argument, std::string("command rejected (") +
                                                         enteron::lcm::rejection_name(reason) + "): " + detail);
    });
}

ENT_API ent_status ent_lcm_bridge_feedback(const ent_lcm_bridge* bridge, int32_t tool, void* buffer,
                                          size_t capacity, size_t* out_size) {
    return guarded([&] {
        require(bridge, "bridge");
        require(buffer, "buffer");
        const Bridge& b = bridge->bridge;
        if (tool < 0 || static_cast<std::size_t>(tool) >= b.tool_count())
            throw Error(ErrorCode::not_found, "tool " + std::to_string(tool) + " does not exist (the scene has " +
                                                  std::to_string(b.tool_count()) + ")");
        const enteron_tool_feedback_t* feedback = b.last_feedback(static_cast<std::size_t>(tool));
        if (feedback == nullptr) throw Error(ErrorCode::not_found, "no feedback before the first tick");
        const int size = enteron_tool_feedback_t_encoded_size(feedback);
        if (out_size != nullptr) *out_size = static_cast<std::size_t>(size);
        if (capacity < static_cast<std::size_t>(size))
            throw Error(ErrorCode::buffer_too_small, "a tool_feedback_t takes " + std::to_string(size) +
                                                         " bytes, capacity is " + std::to_string(capacity));
        enteron_tool_feedback_t_encode(buffer, 0, size, feedback);
    });
}

ENT_API ent_status ent_lcm_bridge_stats(const ent_lcm_bridge* bridge, ent_lcm_stats* out) {
    return guarded([&] {
        require(bridge, "bridge");
        require(out, "out");
        enteron::capi::check_struct_size(out->struct_size, {kStatsSizes[0]}, "ent_lcm_stats");
        ent_lcm_stats all{};
        bridge->bridge.counters().fill(all);
        all.struct_size = out->struct_size;
        std::memcpy(out, &all, out->struct_size);
    });
}

ENT_API ent_status ent_lcm_check_message(int32_t type, const void* bytes, size_t size) {
    return guarded([&] {
        if (!enteron::lcm::known_message_type(type))
            throw Error(ErrorCode::not_found, "unknown message type " + std::to_string(type) + " (ENT_LCM_*)");
        if (bytes == nullptr && size > 0) throw Error(ErrorCode::invalid_argument, "bytes must not be NULL");
        static const unsigned char nothing = 0;
        char detail[256] = "";
        if (enteron::lcm::check_message(type, bytes != nullptr ? bytes : &nothing, size, detail, sizeof detail) !=
            enteron::lcm::MessageFault::none)
            throw Error(ErrorCode::invalid_argument, detail);
    });
}

ENT_API ent_status ent_lcm_replay_journal(const char* path, const ent_callbacks* callbacks,
                                         ent_lcm_replay_result* out) {
    return guarded([&] {
        require(path, "path");
        require(out, "out");
        enteron::capi::check_struct_size(out->struct_size, {sizeof(ent_lcm_replay_result)}, "ent_lcm_replay_result");
        ent_lcm_replay_result result;
        enteron::lcm::replay_journal(path, callbacks, result);
        std::memcpy(out, &result, sizeof result);
    });
}

}  // extern "C"
