// SPDX-License-Identifier: Apache-2.0
// The library's log (lib/base/logger.h): without a callback it is silent and says so
// (enabled() is false); with one every line reaches it formatted, with its level and the
// caller's pointer; a line longer than the stack buffer is cut, never overflowed.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/logger.h"

namespace enteron {
namespace {

struct Lines {
    std::vector<std::pair<int32_t, std::string>> lines;
    static void record(void* user, int32_t level, const char* message) {
        static_cast<Lines*>(user)->lines.emplace_back(level, message);
    }
};

TEST(Logger, WithoutACallbackItIsSilent) {
    const Logger silent;
    EXPECT_FALSE(silent.enabled());
    silent.log(LogLevel::error, "nobody hears %d", 42);  // must not crash
}

TEST(Logger, EveryLineReachesTheCallbackFormattedWithItsLevel) {
    Lines lines;
    const Logger logger(Lines::record, &lines);
    EXPECT_TRUE(logger.enabled());
    logger.log(LogLevel::warning, "step %d: %.2f m", 7, 0.125);
    logger.log(LogLevel::debug, "plain");
    ASSERT_EQ(lines.lines.size(), 2u);
    EXPECT_EQ(lines.lines[0], std::make_pair(int32_t{2}, std::string("step 7: 0.12 m")));
    EXPECT_EQ(lines.lines[1], std::make_pair(int32_t{0}, std::string("plain")));
}

TEST(Logger, ALongLineIsCutToTheBuffer) {
    Lines lines;
    const Logger logger(Lines::record, &lines);
    const std::string long_text(2000, 'x');
    logger.log(LogLevel::info, "%s", long_text.c_str());
    ASSERT_EQ(lines.lines.size(), 1u);
    EXPECT_EQ(lines.lines[0].second, std::string(511, 'x'));
}

}  // namespace
}  // namespace enteron
