// SPDX-License-Identifier: Apache-2.0
// The receive side (command_receiver.h): every reason a command is rejected for, counted
// and logged once per reason then summed; sequences, gaps, a restarted sender, coalescing.
#include <gtest/gtest.h>

#include <lcmtypes/enteron_tool_command_t.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "lcm/command_receiver.h"

namespace enteron::lcm {
namespace {

constexpr int64_t kMs = 1000000;

std::vector<std::string> log_lines;
void collect(void*, int32_t, const char* message) { log_lines.emplace_back(message); }

class CommandReceiverTest : public ::testing::Test {
protected:
    CommandReceiverTest() : callbacks_(host(), counters), receiver(2, mapping, 30 * kMs, counters, callbacks_) {
        log_lines.clear();
    }
    static const ent_callbacks* host() {
        static ent_callbacks callbacks = [] {
            ent_callbacks c;
            ent_callbacks_default(&c);
            c.log = collect;
            return c;
        }();
        return &callbacks;
    }

    static enteron_tool_command_t valid(int64_t seq, int32_t tool = 0) {
        enteron_tool_command_t c{};
        c.seq = seq;
        c.tool = tool;
        c.utime = 100 + seq % 1000;
        c.position_m[0] = 0.01 * static_cast<double>(seq % 10);
        c.orientation_wxyz[0] = 1.0;
        c.force_enable = 1;
        return c;
    }
    static std::vector<uint8_t> bytes_of(const enteron_tool_command_t& c) {
        std::vector<uint8_t> bytes(static_cast<std::size_t>(enteron_tool_command_t_encoded_size(&c)));
        enteron_tool_command_t_encode(bytes.data(), 0, static_cast<int>(bytes.size()), &c);
        return bytes;
    }
    Rejection feed(const enteron_tool_command_t& c, int64_t at_ns = 0) {
        const std::vector<uint8_t> bytes = bytes_of(c);
        return receiver.feed(bytes.data(), bytes.size(), at_ns, detail, sizeof detail);
    }
    int64_t rejected(Rejection reason) const { return counters.rejected[static_cast<int>(reason)].load(); }

    BridgeCounters counters;
    WorkspaceMapping mapping;
    HostCallbacks callbacks_;
    CommandReceiver receiver;
    char detail[256] = "";
};

TEST_F(CommandReceiverTest, EachReasonIsCountedAndNamed) {
    std::vector<uint8_t> short_bytes = bytes_of(valid(1));
    short_bytes.pop_back();
    EXPECT_EQ(receiver.feed(short_bytes.data(), short_bytes.size(), 0, detail, sizeof detail), Rejection::size);
    std::vector<uint8_t> foreign = bytes_of(valid(1));
    foreign[0] ^= 0x80;
    EXPECT_EQ(receiver.feed(foreign.data(), foreign.size(), 0, detail, sizeof detail), Rejection::fingerprint);
    enteron_tool_command_t nan = valid(1);
    nan.linear_velocity_m_per_s[2] = std::nan("");
    EXPECT_EQ(feed(nan), Rejection::not_finite);
    enteron_tool_command_t zero = valid(1);
    zero.orientation_wxyz[0] = 0.0;
    EXPECT_EQ(feed(zero), Rejection::zero_quaternion);
    EXPECT_EQ(feed(valid(1, 2)), Rejection::unknown_tool);
    EXPECT_NE(std::string(detail).find("tool 2 does not exist"), std::string::npos) << detail;
    EXPECT_EQ(feed(valid(1, -1)), Rejection::unknown_tool);
    enteron_tool_command_t level = valid(1);
    level.grasp = 2;
    EXPECT_EQ(feed(level), Rejection::out_of_range);
    enteron_tool_command_t far = valid(1);
    far.position_m[1] = 1e300;
    EXPECT_EQ(feed(far), Rejection::out_of_range);
    for (Rejection reason : {Rejection::size, Rejection::fingerprint, Rejection::not_finite, Rejection::zero_quaternion,
                             Rejection::out_of_range})
        EXPECT_EQ(rejected(reason), reason == Rejection::out_of_range ? 2 : 1) << rejection_name(reason);
    EXPECT_EQ(rejected(Rejection::unknown_tool), 2);
    EXPECT_EQ(counters.commands_received.load(), 8);
    EXPECT_EQ(counters.commands_accepted.load(), 0);
    EXPECT_FALSE(receiver.mailbox(0).take()) << "nothing rejected reaches the tick";
}

TEST_F(CommandReceiverTest, HugeAndTinyQuaternionsAreNormalisedNotOverflowed) {
    enteron_tool_command_t huge = valid(1);
    huge.orientation_wxyz[0] = 1e300;
    huge.orientation_wxyz[1] = 1e300;
    ASSERT_EQ(feed(huge), Rejection::none);
    ASSERT_TRUE(receiver.mailbox(0).take());
    const Eigen::Quaterniond q = receiver.mailbox(0).front().scene_pose.orientation;
    EXPECT_NEAR(q.w(), std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(q.x(), std::sqrt(0.5), 1e-12);
    enteron_tool_command_t tiny = valid(2);
    tiny.orientation_wxyz[0] = 1e-9;
    EXPECT_EQ(feed(tiny), Rejection::zero_quaternion);
}

TEST_F(CommandReceiverTest, SequencesMustIncreaseGapsAreCountedAndTheNewestWins) {
    EXPECT_EQ(feed(valid(5)), Rejection::none);
    EXPECT_EQ(feed(valid(5)), Rejection::sequence) << "repeated";
    EXPECT_EQ(feed(valid(4)), Rejection::sequence) << "decreasing";
    EXPECT_EQ(feed(valid(9)), Rejection::none) << "a gap of 3";
    EXPECT_EQ(counters.sequence_gaps.load(), 1);
    EXPECT_EQ(counters.commands_missed.load(), 3);
    EXPECT_EQ(counters.commands_coalesced.load(), 1) << "5 was replaced by 9 before a tick took it";
    ASSERT_TRUE(receiver.mailbox(0).take());
    EXPECT_EQ(receiver.mailbox(0).front().seq, 9);
    EXPECT_EQ(feed(valid(1, 1)), Rejection::none) << "each tool has its own sequence";
    // The extremes of int64 neither overflow nor wrap.
    EXPECT_EQ(feed(valid(std::numeric_limits<int64_t>::max())), Rejection::none);
    EXPECT_EQ(counters.commands_missed.load(), 3 + (std::numeric_limits<int64_t>::max() - 10));
    EXPECT_EQ(feed(valid(std::numeric_limits<int64_t>::min())), Rejection::sequence);
}

TEST_F(CommandReceiverTest, ASenderSilentForTheWatchdogTimeMayStartANewSequence) {
    EXPECT_EQ(feed(valid(1000), 0), Rejection::none);
    EXPECT_EQ(feed(valid(1), 20 * kMs), Rejection::sequence) << "20 ms later: still the old sender";
    EXPECT_EQ(feed(valid(1), 31 * kMs), Rejection::none) << "31 ms of silence: a restarted sender";
    EXPECT_EQ(feed(valid(2), 32 * kMs), Rejection::none);
}

TEST_F(CommandReceiverTest, TheFirstRejectionOfEachReasonIsLoggedThenTheyAreSummed) {
    enteron_tool_command_t nan = valid(1);
    nan.position_m[0] = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 100; ++i) feed(nan);
    feed(valid(1, 7));
    ASSERT_EQ(log_lines.size(), 2u);
    EXPECT_NE(log_lines[0].find("rejected a command (not finite)"), std::string::npos) << log_lines[0];
    EXPECT_NE(log_lines[1].find("(unknown tool)"), std::string::npos) << log_lines[1];
    receiver.log_summary(1.0);
    ASSERT_EQ(log_lines.size(), 3u);
    EXPECT_NE(log_lines[2].find("rejected 99 more commands in the last 1.0 s: 99 not finite"), std::string::npos)
        << log_lines[2];
    receiver.log_summary(1.0);
    EXPECT_EQ(log_lines.size(), 3u) << "nothing new, nothing logged";
}

}  // namespace
}  // namespace enteron::lcm
