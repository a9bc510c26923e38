// SPDX-License-Identifier: Apache-2.0
// A command in, the feedback of that tick out, in one process over memq:// (the bridge's own
// LCM instance, ent_lcm_bridge_lcm): the feedback carries the command's seq and utime and a
// force within the tool's bound. Then the bridge's own physics thread: feedback every tick,
// and the state, session and status a viewer or logger reads, each an exact message.
#include <lcm/lcm.h>
#include <lcmtypes/enteron_scene_state_t.h>
#include <lcmtypes/enteron_session_t.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "bridge_test_support.h"

namespace enteron_lcm_test {
namespace {

// Messages of one channel, collected by a handler on the bridge's receive thread.
struct Inbox {
    std::mutex mutex;
    std::condition_variable arrived;
    std::vector<std::vector<uint8_t>> messages;

    static void handler(const lcm_recv_buf_t* buffer, const char*, void* self) {
        auto* inbox = static_cast<Inbox*>(self);
        const auto* data = static_cast<const uint8_t*>(buffer->data);
        std::lock_guard<std::mutex> lock(inbox->mutex);
        inbox->messages.emplace_back(data, data + buffer->data_size);
        inbox->arrived.notify_all();
    }
    // Waits (at most 5 s) until `count` messages are here.
    bool wait_for(std::size_t count) {
        std::unique_lock<std::mutex> lock(mutex);
        return arrived.wait_for(lock, std::chrono::seconds(5), [&] { return messages.size() >= count; });
    }
    std::vector<std::vector<uint8_t>> copy() {
        std::lock_guard<std::mutex> lock(mutex);
        return messages;
    }
};

lcm_t* lcm_of(ent_lcm_bridge* bridge) {
    void* lcm = nullptr;
    EXPECT_EQ(ent_lcm_bridge_lcm(bridge, &lcm), ENT_OK) << ent_lcm_last_error();
    return static_cast<lcm_t*>(lcm);
}

void publish(lcm_t* lcm, const enteron_tool_command_t& c) {
    const std::vector<uint8_t> bytes = encode(c);
    ASSERT_EQ(lcm_publish(lcm, "ENTERON_TOOL_COMMAND", bytes.data(), static_cast<unsigned>(bytes.size())), 0);
}

bool wait_until_accepted(ent_lcm_bridge* bridge, int64_t count) {
    for (int i = 0; i < 5000 && stats(bridge).commands_accepted < count; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return stats(bridge).commands_accepted >= count;
}

TEST(MemqRoundTrip, TheFeedbackOfTheTickCarriesTheCommandAndABoundedForce) {
    Inbox feedback;  // before the bridge: its handler runs until the bridge is destroyed
    ent_lcm_bridge_desc desc = short_bowel_desc();
    desc.lcm_url = "memq://";
    desc.watchdog_s = 10.0;  // ticks by hand, on the real clock: a loaded machine must not trip it
    BridgePtr bridge = make_bridge(desc);
    ASSERT_TRUE(bridge);
    lcm_t* lcm = lcm_of(bridge.get());
    ASSERT_NE(lcm_subscribe(lcm, "ENTERON_TOOL_FEEDBACK", Inbox::handler, &feedback), nullptr);

    // The tool above the bowel lying on the floor, then pressed onto it: a contact force.
    const enteron_tool_command_t pressed = command(7, -0.1, 0.0, 0.06);
    publish(lcm, pressed);
    ASSERT_TRUE(wait_until_accepted(bridge.get(), 1));
    ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), ent_lcm_monotonic_ns()), ENT_OK);
    ent_lcm_bridge_notify(bridge.get());
    ASSERT_TRUE(feedback.wait_for(1));
    const std::vector<uint8_t> bytes = feedback.copy().front();
    ASSERT_EQ(ent_lcm_check_message(ENT_LCM_TOOL_FEEDBACK, bytes.data(), bytes.size()), ENT_OK);
    enteron_tool_feedback_t f{};
    ASSERT_GT(enteron_tool_feedback_t_decode(bytes.data(), 0, static_cast<int>(bytes.size()), &f), 0);
    EXPECT_EQ(f.tick, 1);
    EXPECT_EQ(f.tool, 0);
    EXPECT_EQ(f.command_seq, 7);
    EXPECT_EQ(f.command_utime, pressed.utime);
    EXPECT_GE(f.command_age_us, 0);
    EXPECT_LE(magnitude(f.force_N), kMaxForce_N);
    EXPECT_EQ(f.status & ENTERON_TOOL_FEEDBACK_T_STATUS_NO_COMMAND, 0);

    // Keep it pressed for 300 ticks: the force builds up (its ramp and the contact), bounded.
    double largest = 0.0;
    for (int64_t seq = 8; seq < 308; ++seq) {
        publish(lcm, command(seq, -0.1, 0.0, pressing_height(seq)));
        ASSERT_TRUE(wait_until_accepted(bridge.get(), seq - 6));
        ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), ent_lcm_monotonic_ns()), ENT_OK);
        ent_lcm_bridge_notify(bridge.get());
    }
    ASSERT_TRUE(feedback.wait_for(301));
    for (const std::vector<uint8_t>& message : feedback.copy()) {
        ASSERT_EQ(enteron_tool_feedback_t_decode(message.data(), 0, static_cast<int>(message.size()), &f),
                  static_cast<int>(message.size()));
        ASSERT_TRUE(std::isfinite(magnitude(f.force_N)));
        EXPECT_LE(magnitude(f.force_N), kMaxForce_N);
        largest = std::max(largest, magnitude(f.force_N));
    }
    EXPECT_EQ(f.command_seq, 307) << "the last tick applied the last command";
    EXPECT_GT(largest, 0.05) << "the tool presses on the bowel";
}

TEST(MemqRoundTrip, ThePhysicsThreadSendsFeedbackEveryTickAndTheStateForViewers) {
    Inbox feedback, state, session, status;  // before the bridge, which calls their handler until destroyed
    ent_lcm_bridge_desc desc = short_bowel_desc();
    desc.lcm_url = "memq://";
    desc.state_hz = 100.0;
    BridgePtr bridge = make_bridge(desc);
    ASSERT_TRUE(bridge);
    lcm_t* lcm = lcm_of(bridge.get());
    lcm_subscribe(lcm, "ENTERON_TOOL_FEEDBACK", Inbox::handler, &feedback);
    lcm_subscribe(lcm, "ENTERON_STATE", Inbox::handler, &state);
    lcm_subscribe(lcm, "ENTERON_SESSION", Inbox::handler, &session);
    lcm_subscribe(lcm, "ENTERON_STATUS", Inbox::handler, &status);
    ASSERT_EQ(ent_lcm_bridge_start(bridge.get()), ENT_OK);
    EXPECT_EQ(ent_lcm_bridge_tick(bridge.get(), 0), ENT_ERROR_INVALID_ARGUMENT) << "the physics thread ticks now";
    for (int64_t seq = 1; seq <= 1200; ++seq) {
        publish(lcm, command(seq, -0.1, 0.0, 0.03));
        std::this_thread::sleep_for(std::chrono::microseconds(1000));
    }
    ASSERT_TRUE(status.wait_for(1)) << "a status once a second";
    ASSERT_TRUE(session.wait_for(1));
    ASSERT_EQ(ent_lcm_bridge_stop(bridge.get()), ENT_OK);
    const ent_lcm_stats s = stats(bridge.get());
    EXPECT_GT(s.ticks, 100);

    // Feedback of every tick, in order, none lost (memq loses nothing).
    ASSERT_TRUE(feedback.wait_for(static_cast<std::size_t>(s.ticks)));
    std::vector<std::vector<uint8_t>> received = feedback.copy();
    int64_t last_tick = 0;
    for (const std::vector<uint8_t>& message : received) {
        enteron_tool_feedback_t f{};
        ASSERT_GT(enteron_tool_feedback_t_decode(message.data(), 0, static_cast<int>(message.size()), &f), 0);
        EXPECT_EQ(f.tick, last_tick + 1);
        last_tick = f.tick;
    }

    // The state: exact by its counts, and what a viewer draws.
    ASSERT_TRUE(state.wait_for(2));
    const std::vector<uint8_t> last = state.copy().back();
    ASSERT_EQ(ent_lcm_check_message(ENT_LCM_SCENE_STATE, last.data(), last.size()), ENT_OK) << ent_lcm_last_error();
    enteron_scene_state_t st{};
    ASSERT_GT(enteron_scene_state_t_decode(last.data(), 0, static_cast<int>(last.size()), &st), 0);
    EXPECT_EQ(st.num_control_points, 17);
    EXPECT_EQ(st.num_axis_points, 200);
    EXPECT_EQ(st.num_tools, 1);
    EXPECT_DOUBLE_EQ(st.radius_m, 0.0125);
    EXPECT_DOUBLE_EQ(st.tools[0].max_force_N, 5.0);
    EXPECT_NEAR(st.tools[0].applied_position_m[2], 0.03, 1e-9) << "the tool reached the command";
    EXPECT_NE(st.state_digest, 0);
    enteron_scene_state_t_decode_cleanup(&st);

    const std::vector<uint8_t> first_session = session.copy().front();
    ASSERT_EQ(ent_lcm_check_message(ENT_LCM_SESSION, first_session.data(), first_session.size()), ENT_OK);
    enteron_session_t se{};
    ASSERT_GT(enteron_session_t_decode(first_session.data(), 0, static_cast<int>(first_session.size()), &se), 0);
    EXPECT_EQ(std::string(se.scene_json), kShortBowel);
    EXPECT_EQ(se.num_tools, 1);
    EXPECT_EQ(se.session_id, s.session_id);
    EXPECT_DOUBLE_EQ(se.watchdog_s, 0.030);
    enteron_session_t_decode_cleanup(&se);
}

}  // namespace
}  // namespace enteron_lcm_test
