// SPDX-License-Identifier: Apache-2.0
// What the feedback's status tells a device (issue 27, defects 6 and 7):
// - STATUS_FORCE_LIMITED when libenteron bounded the force at the tool's max_force
//   (ent_tool_feedback.saturated): before, the bridge compared the force with max_force
//   after the library had already clamped it there, and 1346 ticks at exactly 5.000 N went
//   out with status 0;
// - STATUS_COMMANDS_REJECTED and the reason in bits 8-15 while a device's commands are
//   rejected: before, a device restarted at seq 0 while the old sender lived was rejected
//   1500 times and its feedback said nothing (status 0, the other sender's seq).
#include "bridge_test_support.h"

namespace enteron_lcm_test {
namespace {

int rejection_reason(int32_t status) {
    return (status & ENTERON_TOOL_FEEDBACK_T_REJECTION_MASK) >> ENTERON_TOOL_FEEDBACK_T_REJECTION_SHIFT;
}

TEST(FeedbackStatus, AForceBoundedAtMaxForceIsSaidLimited) {
    // The tool goes down 3 cm into the bowel on the floor: the coupling would pull far more
    // than 5 N, the library bounds it (the force is exactly max_force, which the device
    // renders once the ramp is done).
    BridgePtr bridge = make_bridge(short_bowel_desc());
    ASSERT_TRUE(bridge);
    int64_t limited_at_max = 0, at_max = 0, limited_below_half = 0;
    for (int64_t tick = 1; tick <= 600; ++tick) {
        const double height = tick < 150 ? 0.06 : 0.0;
        ASSERT_EQ(feed(bridge.get(), command(tick, kPressX_m, 0.0, height), tick * kMs), ENT_OK);
        ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), tick * kMs), ENT_OK);
        const enteron_tool_feedback_t f = feedback(bridge.get());
        const bool limited = (f.status & ENTERON_TOOL_FEEDBACK_T_STATUS_FORCE_LIMITED) != 0;
        const double force = magnitude(f.force_N);
        if (force >= kMaxForce_N * (1 - 1e-9)) {
            ++at_max;
            limited_at_max += limited ? 1 : 0;
        }
        if (tick < 140) limited_below_half += limited ? 1 : 0;  // in the air: nothing bounded
    }
    EXPECT_GT(at_max, 100) << "the press saturates the tool";
    EXPECT_EQ(limited_at_max, at_max) << "every tick at max_force says so";
    EXPECT_EQ(limited_below_half, 0);
}

TEST(FeedbackStatus, ADeviceLockedOutHearsWhyItsCommandsAreRejected) {
    // Device A sends from seq 1 every tick; at tick 200 device B starts for the same tool at
    // seq 0 (a restarted driver while A still lives); A stops at tick 400, B goes on.
    BridgePtr bridge = make_bridge(short_bowel_desc());
    ASSERT_TRUE(bridge);
    int64_t seq_a = 0, seq_b = -1;
    int64_t rejected_ticks = 0, told_ticks = 0, wrong_reason = 0, told_after_b_accepted = 0;
    for (int64_t tick = 1; tick <= 600; ++tick) {
        const int64_t now = tick * kMs;
        if (tick <= 400) {
            ASSERT_EQ(feed(bridge.get(), command(++seq_a, kPressX_m, 0.0, 0.06), now), ENT_OK);
        }
        bool b_rejected = false;
        if (tick >= 200) {
            const ent_status status = feed(bridge.get(), command(++seq_b, kPressX_m, 0.0, 0.06), now);
            b_rejected = status != ENT_OK;
        }
        ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), now), ENT_OK);
        const enteron_tool_feedback_t f = feedback(bridge.get());
        const bool told = (f.status & ENTERON_TOOL_FEEDBACK_T_STATUS_COMMANDS_REJECTED) != 0;
        if (b_rejected) {
            ++rejected_ticks;
            told_ticks += told ? 1 : 0;
            wrong_reason += rejection_reason(f.status) == ENTERON_TOOL_FEEDBACK_T_REJECTED_SEQUENCE ? 0 : 1;
            // B tells it is the one locked out: the command applied is not its own.
            EXPECT_NE(f.command_seq, seq_b);
        }
        if (tick > 400 + 30 + 35 && told) ++told_after_b_accepted;  // the watchdog time after B took over
        if (tick < 200) {
            EXPECT_EQ(f.status & ENTERON_TOOL_FEEDBACK_T_STATUS_COMMANDS_REJECTED, 0);
        }
    }
    EXPECT_GT(rejected_ticks, 150);
    EXPECT_EQ(told_ticks, rejected_ticks) << "every tick after a rejection says so";
    EXPECT_EQ(wrong_reason, 0) << "the reason is the sequence";
    EXPECT_EQ(told_after_b_accepted, 0) << "the bit clears once the rejections stop";
    EXPECT_EQ(stats(bridge.get()).rejected_sequence, rejected_ticks);
}

TEST(FeedbackStatus, ACommandNoToolCanBeReadFromIsToldToEveryTool) {
    BridgePtr bridge = make_bridge(short_bowel_desc());
    ASSERT_TRUE(bridge);
    ASSERT_EQ(feed(bridge.get(), command(1, kPressX_m, 0.0, 0.06), kMs), ENT_OK);
    const uint8_t garbage[7] = {1, 2, 3, 4, 5, 6, 7};
    EXPECT_NE(ent_lcm_bridge_feed_command(bridge.get(), garbage, sizeof garbage, kMs), ENT_OK);
    ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), kMs), ENT_OK);
    const enteron_tool_feedback_t f = feedback(bridge.get());
    EXPECT_NE(f.status & ENTERON_TOOL_FEEDBACK_T_STATUS_COMMANDS_REJECTED, 0);
    EXPECT_EQ(rejection_reason(f.status), ENTERON_TOOL_FEEDBACK_T_REJECTED_SIZE);
    // After the watchdog time without rejections the bit is gone.
    for (int64_t tick = 2; tick <= 40; ++tick) {
        ASSERT_EQ(feed(bridge.get(), command(tick, kPressX_m, 0.0, 0.06), tick * kMs), ENT_OK);
        ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), tick * kMs), ENT_OK);
    }
    EXPECT_EQ(feedback(bridge.get()).status & ENTERON_TOOL_FEEDBACK_T_STATUS_COMMANDS_REJECTED, 0);
}

}  // namespace
}  // namespace enteron_lcm_test
