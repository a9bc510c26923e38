// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the LCM bridge's command path, bytes in, ticks run. A bridge without a
// network (lcm_url "") on a 0.4 m bowel with one tool, with safety settings picked by the
// first bytes (workspace scale, rotation, force scale, device limit, change limit, ramp),
// then up to 256 operations read from the rest:
//   0: raw bytes as a message on ENTERON_TOOL_COMMAND (a length byte, then that many bytes)
//   1: a well-formed tool_command_t (the right size and fingerprint) whose fields come from
//      the bytes: seq steps that may repeat or go back, a tool that may not exist, numbers
//      that may be NaN, infinite, huge or zero, levels that may not be 0 or 1
//   2: time passes (up to 64 ms, so the watchdog trips), then a tick
//   3: a tick 1 ms later
// After every tick the feedback must decode, be finite, and its force stay within
// min(max_force x force_scale, device limit); with AddressSanitizer (scripts/fuzz), no tick
// after the third may allocate on the ticking thread. Any violation aborts.
//
// The bytes are read front to back; tests/fuzz/corpus/lcm_command/ holds seeds made by
// tests/fuzz/make_lcm_seeds.py.
#include <enteron/enteron_lcm.h>
#include <lcmtypes/enteron_tool_command_t.h>
#include <lcmtypes/enteron_tool_feedback_t.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "../lcm/short_bowel_scene.h"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ENTERON_FUZZ_COUNTS_ALLOCATIONS 1
#include <sanitizer/allocator_interface.h>
#endif
#endif

namespace {

#ifdef ENTERON_FUZZ_COUNTS_ALLOCATIONS
// Allocations on the ticking thread while a counted tick runs.
thread_local bool counting = false;
std::atomic<long> tick_allocations{0};
void on_malloc(const volatile void*, size_t) {
    if (counting) tick_allocations.fetch_add(1);
}
void on_free(const volatile void*) {}
#endif

class Bytes {
public:
    Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    bool empty() const { return at_ >= size_; }
    uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
    int16_t i16() { return static_cast<int16_t>(u8() | (u8() << 8)); }
    // A coordinate: usually a few centimetres (x 1e-4 per step), sometimes an edge value.
    double number(double unit) {
        switch (u8() % 16) {
            case 0: return std::numeric_limits<double>::quiet_NaN();
            case 1: return std::numeric_limits<double>::infinity();
            case 2: return -1e300;
            case 3: return -0.0;
            case 4: return std::numeric_limits<double>::denorm_min();
            default: return unit * i16();
        }
    }
    const uint8_t* take(size_t count, size_t& taken) {
        taken = std::min(count, size_ - std::min(at_, size_));
        const uint8_t* p = data_ + std::min(at_, size_);
        at_ += taken;
        return p;
    }

private:
    const uint8_t* data_;
    size_t size_;
    size_t at_ = 0;
};

[[noreturn]] void violation(const char* what, double value) {
    std::fprintf(stderr, "fuzz_lcm_command: %s (%g)\n", what, value);
    std::abort();
}

void check_feedback(ent_lcm_bridge* bridge, double bound) {
    uint8_t bytes[512];
    size_t size = 0;
    if (ent_lcm_bridge_feedback(bridge, 0, bytes, sizeof bytes, &size) != ENT_OK) violation("no feedback", 0);
    enteron_tool_feedback_t f;
    if (enteron_tool_feedback_t_decode(bytes, 0, static_cast<int>(size), &f) != static_cast<int>(size))
        violation("the feedback does not decode", static_cast<double>(size));
    const double magnitude = std::sqrt(f.force_N[0] * f.force_N[0] + f.force_N[1] * f.force_N[1] + f.force_N[2] * f.force_N[2]);
    if (!std::isfinite(magnitude)) violation("the force is not finite", magnitude);
    if (magnitude > bound * (1.0 + 1e-9)) violation("the force exceeds its bound", magnitude);
    for (double value : f.torque_Nm)
        if (!std::isfinite(value)) violation("the torque is not finite", value);
    for (double value : f.applied_position_m)
        if (!std::isfinite(value)) violation("the applied position is not finite", value);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
#ifdef ENTERON_FUZZ_COUNTS_ALLOCATIONS
    static const bool hooked = __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free) != 0;
    (void)hooked;
#endif
    Bytes in(data, size);
    ent_lcm_bridge_desc desc;
    ent_lcm_bridge_desc_default(&desc);
    desc.scene_json = kShortBowelScene;
    desc.scene_json_length = sizeof kShortBowelScene - 1;
    desc.lcm_url = "";
    desc.state_hz = 0.0;
    const uint8_t settings = in.u8();
    if (settings & 1) desc.workspace_scale = 0.001;
    if (settings & 2) {
        desc.workspace_rotation_wxyz[0] = 1.0 + in.u8() % 3 - 1;
        desc.workspace_rotation_wxyz[1] = in.u8() % 3 - 1.0;
        desc.workspace_rotation_wxyz[2] = 1.0;
    }
    if (settings & 4) desc.force_scale = 0.25 + in.u8() / 32.0;
    if (settings & 8) desc.device_max_force = 0.5 + in.u8() / 16.0;
    if (settings & 16) desc.max_force_change_per_tick = 0.01 + in.u8() / 256.0;
    if (settings & 32) desc.force_ramp_s = in.u8() / 512.0;
    if (settings & 64) desc.watchdog_s = 0.001 + in.u8() / 4096.0;
    ent_lcm_bridge* bridge = nullptr;
    if (ent_lcm_bridge_create(&desc, &bridge) != ENT_OK) violation("the bridge cannot be made", 0);
    double bound = kShortBowelMaxForce_N * desc.force_scale;
    if (desc.device_max_force > 0.0) bound = std::min(bound, desc.device_max_force);

    int64_t now_ns = 0, seq = 0;
    int ticks = 0;
    const auto tick = [&](int64_t advance_ns) {
        now_ns += advance_ns;
#ifdef ENTERON_FUZZ_COUNTS_ALLOCATIONS
        counting = ticks >= 3;
#endif
        const ent_status status = ent_lcm_bridge_tick(bridge, now_ns);
#ifdef ENTERON_FUZZ_COUNTS_ALLOCATIONS
        counting = false;
        if (tick_allocations.exchange(0) != 0) violation("a tick after the third allocated", ticks);
#endif
        if (status != ENT_OK) violation("a tick failed", status);
        ++ticks;
        check_feedback(bridge, bound);
    };
    for (int operation = 0; operation < 256 && !in.empty(); ++operation) {
        switch (in.u8() % 4) {
            case 0: {
                size_t taken = 0;
                const uint8_t* bytes = in.take(in.u8(), taken);
                ent_lcm_bridge_feed_command(bridge, bytes, taken, now_ns);
                break;
            }
            case 1: {
                enteron_tool_command_t c{};
                seq += static_cast<int>(in.u8() % 4) - 1;
                c.seq = seq;
                c.utime = now_ns / 1000;
                c.tool = static_cast<int32_t>(in.u8() % 5) - 1 == 3 ? 1 : 0;
                const double unit = desc.workspace_scale == 1.0 ? 1e-4 : 0.1;
                for (double& value : c.position_m) value = in.number(unit);
                for (double& value : c.orientation_wxyz) value = in.number(1.0 / 8192);
                for (double& value : c.linear_velocity_m_per_s) value = in.number(1e-3);
                c.grasp = static_cast<int8_t>(in.u8() % 3);
                c.force_enable = static_cast<int8_t>(in.u8() % 3 == 0 ? 0 : 1);
                c.buttons = in.u8();
                uint8_t bytes[256];
                const int length = enteron_tool_command_t_encode(bytes, 0, sizeof bytes, &c);
                ent_lcm_bridge_feed_command(bridge, bytes, static_cast<size_t>(length), now_ns);
                break;
            }
            case 2: tick(static_cast<int64_t>(in.u8()) * 250000); break;
            default: tick(1000000); break;
        }
    }
    ent_lcm_bridge_destroy(bridge);
    return 0;
}
