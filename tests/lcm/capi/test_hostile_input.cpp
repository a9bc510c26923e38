// SPDX-License-Identifier: Apache-2.0
// Hostile input on the command path: wrong size, wrong fingerprint, NaN, a zero quaternion,
// an unknown tool, repeated and decreasing seq, bytes that are not a message at all, and a
// flood of 100 000 commands while the physics thread runs: every one rejected or
// coalesced, counted by reason, none applied, the scene unharmed and still stepping.
#include <lcmtypes/enteron_journal_step_t.h>

#include <chrono>
#include <limits>
#include <random>
#include <thread>

#include "bridge_test_support.h"

namespace enteron_lcm_test {
namespace {

int64_t rejected_total(const ent_lcm_stats& s) {
    return s.rejected_size + s.rejected_fingerprint + s.rejected_not_finite + s.rejected_zero_quaternion +
           s.rejected_unknown_tool + s.rejected_sequence + s.rejected_out_of_range;
}

TEST(HostileInput, EachKindIsRejectedCountedByReasonAndNeverApplied) {
    BridgePtr bridge = make_bridge(short_bowel_desc());
    ASSERT_TRUE(bridge);
    ASSERT_EQ(feed(bridge.get(), command(10, 0.0, 0.06, 0.05), 0), ENT_OK);
    ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), 0), ENT_OK);

    std::vector<uint8_t> bytes = encode(command(11, 0.0, 0.0, 0.0));
    bytes.pop_back();
    EXPECT_EQ(ent_lcm_bridge_feed_command(bridge.get(), bytes.data(), bytes.size(), 0), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(ent_lcm_last_error()).find("(size)"), std::string::npos) << ent_lcm_last_error();
    bytes = encode(command(11, 0.0, 0.0, 0.0));
    bytes[7] ^= 0x55;
    EXPECT_EQ(ent_lcm_bridge_feed_command(bridge.get(), bytes.data(), bytes.size(), 0), ENT_ERROR_INVALID_ARGUMENT);
    enteron_journal_step_t step{};  // another type of ours, padded to the command's size
    std::vector<uint8_t> other(bytes.size());
    enteron_journal_step_t_encode(other.data(), 0, static_cast<int>(other.size()), &step);
    EXPECT_EQ(ent_lcm_bridge_feed_command(bridge.get(), other.data(), other.size(), 0), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_lcm_bridge_feed_command(bridge.get(), nullptr, 0, 0), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_lcm_bridge_feed_command(bridge.get(), nullptr, 5, 0), ENT_ERROR_INVALID_ARGUMENT);

    enteron_tool_command_t c = command(11, std::nan(""), 0.0, 0.0);
    EXPECT_EQ(feed(bridge.get(), c, 0), ENT_ERROR_INVALID_ARGUMENT);
    c = command(11, 0.0, 0.0, 0.0);
    c.orientation_wxyz[3] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(feed(bridge.get(), c, 0), ENT_ERROR_INVALID_ARGUMENT);
    c = command(11, 0.0, 0.0, 0.0);
    c.orientation_wxyz[0] = 0.0;
    EXPECT_EQ(feed(bridge.get(), c, 0), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(ent_lcm_last_error()).find("zero"), std::string::npos) << ent_lcm_last_error();
    c = command(11, 0.0, 0.0, 0.0);
    c.tool = 1;
    EXPECT_EQ(feed(bridge.get(), c, 0), ENT_ERROR_INVALID_ARGUMENT);
    c.tool = std::numeric_limits<int32_t>::min();
    EXPECT_EQ(feed(bridge.get(), c, 0), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(feed(bridge.get(), command(10, 0.0, 0.0, 0.0), 0), ENT_ERROR_INVALID_ARGUMENT) << "repeated seq";
    EXPECT_EQ(feed(bridge.get(), command(9, 0.0, 0.0, 0.0), 0), ENT_ERROR_INVALID_ARGUMENT) << "decreasing seq";
    c = command(11, 0.0, 0.0, 0.0);
    c.force_enable = -1;
    EXPECT_EQ(feed(bridge.get(), c, 0), ENT_ERROR_INVALID_ARGUMENT);

    const ent_lcm_stats s = stats(bridge.get());
    EXPECT_EQ(s.rejected_size, 2) << "the short message and the empty one";
    EXPECT_EQ(s.rejected_fingerprint, 2);
    EXPECT_EQ(s.rejected_not_finite, 2);
    EXPECT_EQ(s.rejected_zero_quaternion, 1);
    EXPECT_EQ(s.rejected_unknown_tool, 2);
    EXPECT_EQ(s.rejected_sequence, 2);
    EXPECT_EQ(s.rejected_out_of_range, 1);
    EXPECT_EQ(s.commands_accepted, 1);
    EXPECT_EQ(s.commands_received, 1 + rejected_total(s)) << "the NULL with size 5 never reached the receiver";

    // None of them was applied: the tool keeps going to where the accepted command said.
    for (int tick = 2; tick <= 100; ++tick) ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), tick), ENT_OK);
    const enteron_tool_feedback_t f = feedback(bridge.get());
    EXPECT_EQ(f.command_seq, 10);
    EXPECT_DOUBLE_EQ(f.applied_position_m[2], 0.05);
}

// 100 000 commands from another thread, as fast as it can, while the physics thread ticks:
// half valid (increasing seq), half hostile. Afterwards everything adds up, the bowel's
// state is finite and no step failed.
TEST(HostileInput, AFloodIsRejectedOrCoalescedWhileTheSceneStepsOn) {
    BridgePtr bridge = make_bridge(short_bowel_desc());
    ASSERT_TRUE(bridge);
    ASSERT_EQ(ent_lcm_bridge_start(bridge.get()), ENT_OK);
    constexpr int kCommands = 100000;
    const int64_t ticks_before = stats(bridge.get()).ticks;
    int64_t valid = 0, invalid = 0;
    std::thread flood([&] {
        std::mt19937 random(12345);
        int64_t seq = 0;
        for (int i = 0; i < kCommands; ++i) {
            enteron_tool_command_t c = command(++seq, -0.1 + 0.0001 * (i % 1000), 0.0, 0.02 + 0.00001 * (i % 100));
            std::vector<uint8_t> bytes;
            switch (random() % 8) {
                case 0: c.position_m[random() % 3] = std::nan(""); break;
                case 1: c.orientation_wxyz[0] = 0.0; break;
                case 2: c.tool = static_cast<int32_t>(random()); break;
                case 3: c.seq = seq - 5; break;
                default: break;
            }
            bytes = encode(c);
            if (random() % 16 == 0) bytes.resize(random() % bytes.size());
            if (random() % 16 == 0) bytes[random() % 8] ^= 0xFF;
            const bool accepted = ent_lcm_bridge_feed_command(bridge.get(), bytes.data(), bytes.size(),
                                                              ent_lcm_monotonic_ns()) == ENT_OK;
            (accepted ? valid : invalid) += 1;
        }
    });
    flood.join();
    // The physics thread keeps ticking through the flood; how fast depends on the machine's
    // load, so wait for its ticks (a bound against a hang only) instead of a fixed time.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (stats(bridge.get()).ticks - ticks_before <= 10 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_EQ(ent_lcm_bridge_stop(bridge.get()), ENT_OK);
    const ent_lcm_stats s = stats(bridge.get());
    EXPECT_EQ(s.commands_received, kCommands);
    EXPECT_EQ(s.commands_accepted, valid);
    EXPECT_EQ(rejected_total(s), invalid);
    EXPECT_GT(s.rejected_size, 0);
    EXPECT_GT(s.rejected_fingerprint, 0);
    EXPECT_GT(s.rejected_not_finite, 0);
    EXPECT_GT(s.rejected_zero_quaternion, 0);
    EXPECT_GT(s.rejected_unknown_tool, 0);
    EXPECT_GT(s.rejected_sequence, 0);
    EXPECT_GT(s.commands_coalesced, valid / 2) << "many more commands than ticks: most were never applied";
    EXPECT_EQ(s.step_failures, 0);
    EXPECT_GT(s.ticks - ticks_before, 10) << "the physics thread kept ticking";
    std::printf("flood: %d commands, %lld accepted (%lld coalesced), %lld rejected, %lld ticks, %lld missed deadlines\n",
                kCommands, static_cast<long long>(s.commands_accepted), static_cast<long long>(s.commands_coalesced),
                static_cast<long long>(rejected_total(s)), static_cast<long long>(s.ticks - ticks_before),
                static_cast<long long>(s.missed_deadlines));

    double points[3 * 17];
    uint32_t count = 0;
    ASSERT_EQ(ent_scene_control_points(ent_lcm_bridge_scene(bridge.get()), 17, points, &count), ENT_OK);
    for (uint32_t i = 0; i < 3 * count; ++i) ASSERT_TRUE(std::isfinite(points[i]));
    for (uint32_t i = 0; i < count; ++i) EXPECT_LT(std::fabs(points[3 * i + 1]), 0.15) << "still inside the box";
    const enteron_tool_feedback_t f = feedback(bridge.get());
    EXPECT_LE(magnitude(f.force_N), kMaxForce_N);
}

}  // namespace
}  // namespace enteron_lcm_test
