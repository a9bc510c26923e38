// SPDX-License-Identifier: Apache-2.0
// The journal: a 10 s session with contacts and a grasp (10 000 ticks, run faster than real
// time by ticking by hand on the bridge's clock) replays bit for bit; a journal with one
// entry changed fails at exactly that tick; a damaged entry is reported at its tick; a
// journal cut short still replays what it holds and says it has no end.
#include <lcmtypes/enteron_journal_tool_t.h>

#include <cstdio>
#include <cstring>
#include <unistd.h>
#include <fstream>
#include <iterator>
#include <string>

#include "bridge_test_support.h"

namespace enteron_lcm_test {
namespace {

std::string temporary_path(const char* name) {
    const char* directory = std::getenv("TMPDIR");
    return std::string(directory != nullptr ? directory : "/tmp") + "/enteron_lcm_" + name + "_" +
           std::to_string(::getpid()) + ".lcmlog";
}

std::vector<uint8_t> read_all(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(file), {});
}

void write_all(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

int64_t big_endian(const uint8_t* p, int bytes) {
    uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | p[i];
    return bytes == 4 ? static_cast<int32_t>(static_cast<uint32_t>(value)) : static_cast<int64_t>(value);
}

// Where, in a journal's bytes, the journal_tool_t entry of `tick` starts (its data).
std::size_t tool_entry_of(const std::vector<uint8_t>& journal, int64_t tick) {
    std::size_t offset = 0;
    while (offset + 28 <= journal.size()) {
        const int64_t channel_length = big_endian(&journal[offset + 20], 4);
        const int64_t data_length = big_endian(&journal[offset + 24], 4);
        const std::string channel(reinterpret_cast<const char*>(&journal[offset + 28]),
                                  static_cast<std::size_t>(channel_length));
        const std::size_t data = offset + 28 + static_cast<std::size_t>(channel_length);
        if (channel == "ENTERON_JOURNAL_TOOL") {
            enteron_journal_tool_t entry{};
            enteron_journal_tool_t_decode(&journal[data], 0, static_cast<int>(data_length), &entry);
            if (entry.tick == tick) return data;
        }
        offset = data + static_cast<std::size_t>(data_length);
    }
    ADD_FAILURE() << "no journal_tool_t for tick " << tick;
    return 0;
}

ent_lcm_replay_result replay(const std::string& path) {
    ent_lcm_replay_result result;
    std::memset(&result, 0, sizeof result);
    result.struct_size = sizeof result;
    EXPECT_EQ(ent_lcm_replay_journal(path.c_str(), nullptr, &result), ENT_OK) << ent_lcm_last_error();
    return result;
}

class JournalReplay : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        path_ = temporary_path("session");
        ent_lcm_bridge_desc desc = short_bowel_desc();
        desc.journal_path = path_.c_str();
        BridgePtr bridge = make_bridge(desc);
        ASSERT_TRUE(bridge);
        const double seconds = 10.0;
        const int64_t ticks = 10000;
        int64_t sent = 0;
        for (int64_t tick = 1; tick <= ticks; ++tick) {
            double position[3];
            bool grasp = false;
            grasp_path(1e-3 * static_cast<double>(tick), seconds, position, grasp);
            // Like a network: now and then a command is lost, or two arrive in one tick.
            if (tick % 97 != 0) {
                ASSERT_EQ(feed(bridge.get(), command(++sent, position[0], position[1], position[2], grasp), tick * kMs),
                          ENT_OK);
                if (tick % 89 == 0) {
                    ASSERT_EQ(feed(bridge.get(), command(++sent, position[0], position[1], position[2], grasp), tick * kMs),
                              ENT_OK);
                }
            }
            ASSERT_EQ(ent_lcm_bridge_tick(bridge.get(), tick * kMs), ENT_OK);
            const enteron_tool_feedback_t f = feedback(bridge.get());
            grasped_ = grasped_ || f.grasping != 0;
            ent_stats s{};
            s.struct_size = sizeof s;
            ent_scene_stats(ent_lcm_bridge_scene(bridge.get()), &s);
            most_contacts_ = std::max<uint32_t>(most_contacts_, s.contacts);
        }
        journal_ = read_all(path_);
        // The end record is written when the bridge is destroyed.
    }
    static void TearDownTestSuite() { std::remove(path_.c_str()); }

    static std::string path_;
    static std::vector<uint8_t> journal_;
    static bool grasped_;
    static uint32_t most_contacts_;
};
std::string JournalReplay::path_;
std::vector<uint8_t> JournalReplay::journal_;
bool JournalReplay::grasped_ = false;
uint32_t JournalReplay::most_contacts_ = 0;

TEST_F(JournalReplay, TenSecondsWithContactsAndAGraspReplayBitForBit) {
    ASSERT_TRUE(grasped_) << "the session must hold a grasp";
    ASSERT_GT(most_contacts_, 0u) << "and contacts";
    const ent_lcm_replay_result result = replay(path_);
    EXPECT_EQ(result.identical, 1) << result.message;
    EXPECT_EQ(result.ticks, 10000);
    EXPECT_EQ(result.complete, 1);
    EXPECT_EQ(result.first_difference_tick, -1);
    EXPECT_STREQ(result.message, "bit-identical over 10000 ticks");
}

TEST_F(JournalReplay, OneChangedEntryFailsAtItsTick) {
    std::vector<uint8_t> changed = read_all(path_);
    // The last byte of the tool's x position at tick 5000: its least significant bits.
    const std::size_t entry = tool_entry_of(changed, 5000);
    const std::size_t position_x = entry + 8 /*fingerprint*/ + 8 /*utime*/ + 8 /*tick*/ + 4 /*tool*/;
    changed[position_x + 7] ^= 0x01;
    const std::string path = temporary_path("changed");
    write_all(path, changed);
    const ent_lcm_replay_result result = replay(path);
    std::remove(path.c_str());
    EXPECT_EQ(result.identical, 0);
    EXPECT_EQ(result.first_difference_tick, 5000) << result.message;
    EXPECT_EQ(result.ticks, 4999);
    EXPECT_NE(result.journal_digest, result.replay_digest);
    EXPECT_NE(std::string(result.message).find("tick 5000 differs"), std::string::npos) << result.message;
}

TEST_F(JournalReplay, ADamagedEntryIsReportedAtItsTick) {
    std::vector<uint8_t> damaged = read_all(path_);
    damaged[tool_entry_of(damaged, 7000)] ^= 0xFF;  // its fingerprint
    const std::string path = temporary_path("damaged");
    write_all(path, damaged);
    const ent_lcm_replay_result result = replay(path);
    std::remove(path.c_str());
    EXPECT_EQ(result.identical, 0);
    EXPECT_EQ(result.first_difference_tick, 7000) << result.message;
    EXPECT_NE(std::string(result.message).find("damaged"), std::string::npos) << result.message;
}

TEST_F(JournalReplay, AJournalCutShortReplaysWhatItHolds) {
    const std::string path = temporary_path("cut");
    write_all(path, std::vector<uint8_t>(journal_.begin(), journal_.begin() + static_cast<long>(tool_entry_of(journal_, 3001)) - 60));
    const ent_lcm_replay_result result = replay(path);
    std::remove(path.c_str());
    EXPECT_EQ(result.complete, 0);
    EXPECT_NE(std::string(result.message).find("no end record"), std::string::npos) << result.message;
}

TEST(JournalReplayErrors, AFileThatIsNotAJournalIsRefusedByName) {
    ent_lcm_replay_result result;
    std::memset(&result, 0, sizeof result);
    result.struct_size = sizeof result;
    EXPECT_EQ(ent_lcm_replay_journal("/nonexistent/journal.lcmlog", nullptr, &result), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(ent_lcm_last_error()).find("/nonexistent/journal.lcmlog"), std::string::npos);
    const std::string path = temporary_path("not_a_journal");
    write_all(path, std::vector<uint8_t>(100, 7));
    EXPECT_EQ(ent_lcm_replay_journal(path.c_str(), nullptr, &result), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(ent_lcm_last_error()).find("not a journal"), std::string::npos) << ent_lcm_last_error();
    std::remove(path.c_str());
    result.struct_size = 3;
    EXPECT_EQ(ent_lcm_replay_journal(path.c_str(), nullptr, &result), ENT_ERROR_VERSION);
}

}  // namespace
}  // namespace enteron_lcm_test
