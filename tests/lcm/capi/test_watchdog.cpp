// SPDX-License-Identifier: Apache-2.0
// The watchdog (the device stops sending): within the watchdog time and one tick the force
// is zero, STALE is set and the tool is held; when commands come back the tool moves at its
// bounded speed and the force ramps back in (its change per tick stays small), where
// without the ramp it would come back as a jolt. On the bridge's own clock, driven by hand.
#include "bridge_test_support.h"

namespace enteron_lcm_test {
namespace {

struct WatchdogRun {
    int64_t stale_tick = -1;         // the first tick with STALE set
    double force_before_stop_N = 0;  // |F| at the last tick with commands
    double largest_change_after_resume_N = 0;
    double largest_move_after_resume_m = 0;
    bool held_while_stale = true;
    bool zero_while_stale = true;
};

// The tool presses onto the bowel for 400 ticks; commands stop at tick 400 (the last one
// received at 400 ms); they come back at tick 500, for a pose 3 cm higher.
WatchdogRun run(double force_ramp_s) {
    ent_lcm_bridge_desc desc = short_bowel_desc();
    desc.force_ramp_s = force_ramp_s;
    BridgePtr bridge = make_bridge(desc);
    WatchdogRun result;
    if (!bridge) return result;
    int64_t seq = 0;
    double previous_force[3] = {0, 0, 0}, previous_position[3] = {0, 0, 0};
    for (int64_t tick = 1; tick <= 700; ++tick) {
        const int64_t now = tick * kMs;
        const bool sending = tick <= 400 || tick > 500;
        if (sending) {
            EXPECT_EQ(feed(bridge.get(), command(++seq, kPressX_m, 0.0, pressing_height(tick) + (tick > 500 ? 0.03 : 0.0)), now), ENT_OK);
        }
        EXPECT_EQ(ent_lcm_bridge_tick(bridge.get(), now), ENT_OK);
        const enteron_tool_feedback_t f = feedback(bridge.get());
        const bool stale = (f.status & ENTERON_TOOL_FEEDBACK_T_STATUS_STALE) != 0;
        if (stale && result.stale_tick < 0) result.stale_tick = tick;
        if (tick == 400) result.force_before_stop_N = magnitude(f.force_N);
        if (stale) {
            result.zero_while_stale = result.zero_while_stale && magnitude(f.force_N) == 0.0;
            for (int c = 0; c < 3; ++c)
                result.held_while_stale = result.held_while_stale && f.applied_position_m[c] == previous_position[c];
        }
        if (tick > 500) {
            const double change[3] = {f.force_N[0] - previous_force[0], f.force_N[1] - previous_force[1],
                                      f.force_N[2] - previous_force[2]};
            const double move[3] = {f.applied_position_m[0] - previous_position[0],
                                    f.applied_position_m[1] - previous_position[1],
                                    f.applied_position_m[2] - previous_position[2]};
            result.largest_change_after_resume_N = std::max(result.largest_change_after_resume_N, magnitude(change));
            result.largest_move_after_resume_m = std::max(result.largest_move_after_resume_m, magnitude(move));
        }
        std::copy(f.force_N, f.force_N + 3, previous_force);
        std::copy(f.applied_position_m, f.applied_position_m + 3, previous_position);
    }
    EXPECT_EQ(stats(bridge.get()).watchdog_trips, 1);
    return result;
}

TEST(Watchdog, ZeroForceAndStaleWithinItsTimeAndOneTickThenNoJolt) {
    const WatchdogRun ramped = run(0.1);
    // The last command arrived at 400 ms; at 430 ms it is 30 ms old (not stale yet), at 431 ms stale.
    EXPECT_EQ(ramped.stale_tick, 431);
    EXPECT_TRUE(ramped.zero_while_stale);
    EXPECT_TRUE(ramped.held_while_stale) << "the tool stays where it was";
    ASSERT_GT(ramped.force_before_stop_N, 0.2) << "the tool pressed on the bowel before the stop";
    // Ramp in over 100 ticks: each tick adds 1 % of the force, plus the contact's own change.
    EXPECT_LT(ramped.largest_change_after_resume_N, 0.1 * ramped.force_before_stop_N);
    EXPECT_LE(ramped.largest_move_after_resume_m, 0.001 + 1e-12) << "1 m/s: 1 mm per tick at most";

    const WatchdogRun unramped = run(0.0);
    EXPECT_GT(unramped.largest_change_after_resume_N, 0.5 * unramped.force_before_stop_N)
        << "without the ramp the force comes back in one tick: the jolt the ramp removes";
}

}  // namespace
}  // namespace enteron_lcm_test
