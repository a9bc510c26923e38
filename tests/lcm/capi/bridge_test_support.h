// SPDX-License-Identifier: Apache-2.0
// What the bridge's C API tests share: the scene, a bridge made from it, commands encoded
// and feedback decoded with lcm-gen's C types, as a device would. Public headers only.
#pragma once

#include <enteron/enteron_lcm.h>
#include <gtest/gtest.h>
#include <lcmtypes/enteron_tool_command_t.h>
#include <lcmtypes/enteron_tool_feedback_t.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "../short_bowel_scene.h"

namespace enteron_lcm_test {

inline constexpr const char* kShortBowel = kShortBowelScene;
constexpr double kMaxForce_N = kShortBowelMaxForce_N;
constexpr int64_t kMs = 1000000;  // ns

struct BridgeDeleter {
    void operator()(ent_lcm_bridge* bridge) const { ent_lcm_bridge_destroy(bridge); }
};
using BridgePtr = std::unique_ptr<ent_lcm_bridge, BridgeDeleter>;

// The default desc for kShortBowel, without any network (lcm_url "") unless changed.
inline ent_lcm_bridge_desc short_bowel_desc() {
    ent_lcm_bridge_desc desc;
    ent_lcm_bridge_desc_default(&desc);
    desc.scene_json = kShortBowel;
    desc.scene_json_length = sizeof kShortBowelScene - 1;
    desc.lcm_url = "";
    return desc;
}

inline BridgePtr make_bridge(const ent_lcm_bridge_desc& desc) {
    ent_lcm_bridge* bridge = nullptr;
    const ent_status status = ent_lcm_bridge_create(&desc, &bridge);
    EXPECT_EQ(status, ENT_OK) << ent_lcm_last_error();
    return BridgePtr(bridge);
}

inline enteron_tool_command_t command(int64_t seq, double x, double y, double z, bool grasp = false,
                                      bool force_enable = true) {
    enteron_tool_command_t c{};
    c.utime = 1000000 + 7 * seq;
    c.seq = seq;
    c.tool = 0;
    c.position_m[0] = x;
    c.position_m[1] = y;
    c.position_m[2] = z;
    c.orientation_wxyz[0] = 1.0;
    c.grasp = grasp ? 1 : 0;
    c.force_enable = force_enable ? 1 : 0;
    return c;
}

// Pressing on the bowel lying on the floor: the tool waits 6 cm above it at x = -0.1 for the
// first 150 ticks (it gets there from its start), then goes down until its tip is 2.4 cm
// above the floor, 6 mm into the bowel: a force of a few newtons, straight up.
constexpr double kPressX_m = -0.1;
inline double pressing_height(int64_t tick) { return tick < 150 ? 0.06 : 0.024; }

inline std::vector<uint8_t> encode(const enteron_tool_command_t& c) {
    std::vector<uint8_t> bytes(static_cast<std::size_t>(enteron_tool_command_t_encoded_size(&c)));
    enteron_tool_command_t_encode(bytes.data(), 0, static_cast<int>(bytes.size()), &c);
    return bytes;
}

inline ent_status feed(ent_lcm_bridge* bridge, const enteron_tool_command_t& c, int64_t at_ns) {
    const std::vector<uint8_t> bytes = encode(c);
    return ent_lcm_bridge_feed_command(bridge, bytes.data(), bytes.size(), at_ns);
}

inline enteron_tool_feedback_t feedback(const ent_lcm_bridge* bridge, int32_t tool = 0) {
    uint8_t bytes[1024];
    size_t size = 0;
    enteron_tool_feedback_t f{};
    EXPECT_EQ(ent_lcm_bridge_feedback(bridge, tool, bytes, sizeof bytes, &size), ENT_OK) << ent_lcm_last_error();
    EXPECT_EQ(ent_lcm_check_message(ENT_LCM_TOOL_FEEDBACK, bytes, size), ENT_OK);
    EXPECT_GT(enteron_tool_feedback_t_decode(bytes, 0, static_cast<int>(size), &f), 0);
    return f;
}

inline double magnitude(const double v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

inline ent_lcm_stats stats(const ent_lcm_bridge* bridge) {
    ent_lcm_stats s{};
    s.struct_size = sizeof s;
    EXPECT_EQ(ent_lcm_bridge_stats(bridge, &s), ENT_OK);
    return s;
}

// The tool's path over the short bowel, as the driver-side example scripts it (metres,
// scene frame): down beside the bowel, across its rest line (it gives way), grasp, lift.
inline void grasp_path(double t_s, double total_s, double position[3], bool& grasp) {
    struct Key {
        double share;
        double to[3];
        bool grasp;
    };
    static const Key keys[] = {{0.15, {0.0, 0.04, 0.0125}, false},  {0.25, {0.0, -0.02, 0.0125}, false},
                               {0.05, {0.0, -0.02, 0.0125}, true},  {0.20, {0.0, -0.02, 0.0925}, true},
                               {0.15, {0.0, -0.02, 0.0925}, true},  {0.20, {0.0, 0.06, 0.06}, false}};
    double from[3] = {0.0, 0.06, 0.06}, begin = 0.0;
    for (const Key& key : keys) {
        const double length = key.share * total_s;
        if (t_s < begin + length || &key == &keys[5]) {
            double a = std::min(1.0, std::max(0.0, (t_s - begin) / length));
            a = a * a * (3.0 - 2.0 * a);
            for (int c = 0; c < 3; ++c) position[c] = from[c] + a * (key.to[c] - from[c]);
            grasp = key.grasp;
            return;
        }
        begin += length;
        for (int c = 0; c < 3; ++c) from[c] = key.to[c];
    }
}

}  // namespace enteron_lcm_test
