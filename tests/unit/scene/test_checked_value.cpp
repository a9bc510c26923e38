// SPDX-License-Identifier: Apache-2.0
// One checked value (lib/scene/checked_value.h): a check that holds passes and chains; one
// that fails throws the code it was given and a message naming the value, the rule, the
// bound (and where the bound comes from) and what was given, written as the shortest text
// that reads back as the same double; a non-finite double fails at once.
#include <gtest/gtest.h>

#include <clocale>
#include <limits>
#include <string>

#include "refusal.h"
#include "scene/checked_value.h"

namespace enteron::scene {
namespace {

// The message of the refusal, the code invalid_scene unless told.
template <class F>
std::string message_of(F check, ErrorCode code = ErrorCode::invalid_scene) {
    return unit_test::refusal(check, code);
}

TEST(CheckedValue, ChecksThatHoldChainAndOnesThatFailSayWhy) {
    EXPECT_EQ(message_of([] { Checked<double>(0.0125, "intestine.radius", ErrorCode::invalid_scene).above(0.0).below(6.0); }),
              "(no refusal)");
    EXPECT_EQ(message_of([] { Checked<double>(-1.0, "intestine.radius", ErrorCode::invalid_scene).above(0.0); }),
              "intestine.radius must be > 0, got -1");
    EXPECT_EQ(message_of([] {
                  Checked<double>(7.0, "intestine.radius", ErrorCode::invalid_argument).above(0.0).below(6.0, "intestine.length");
              }, ErrorCode::invalid_argument),
              "intestine.radius must be < intestine.length (6), got 7");
    EXPECT_EQ(message_of([] { Checked<uint32_t>(3, "control_points", ErrorCode::invalid_scene).at_least(4); }),
              "control_points must be >= 4, got 3");
    EXPECT_EQ(message_of([] { Checked<int>(5, "segments", ErrorCode::invalid_scene).at_most(4); }),
              "segments must be <= 4, got 5");
    EXPECT_EQ(message_of([] { Checked<double>(0.1, "x", ErrorCode::invalid_scene).at_least(0.1).at_most(0.1); }), "(no refusal)");
}

TEST(CheckedValue, ANonFiniteNumberFailsAtOnce) {
    EXPECT_EQ(message_of([] { Checked<double>(std::numeric_limits<double>::quiet_NaN(), "gravity[2]", ErrorCode::invalid_scene); }),
              "gravity[2] must be finite, got nan");
    EXPECT_EQ(message_of([] { Checked<double>(-std::numeric_limits<double>::infinity(), "dt", ErrorCode::invalid_argument); },
                         ErrorCode::invalid_argument),
              "dt must be finite, got -inf");
}

TEST(CheckedValue, NumbersAreTheShortestTextThatReadsBackWhateverTheLocale) {
    EXPECT_EQ(format_number(0.1), "0.1");
    EXPECT_EQ(format_number(-1.0), "-1");
    EXPECT_EQ(format_number(1e-300), "1e-300");
    EXPECT_EQ(std::stod(format_number(0.1 + 0.2)), 0.1 + 0.2);
    EXPECT_EQ(format_number(std::size_t{240}), "240");
    EXPECT_EQ(format_rounded(0.97912), "0.979");
    EXPECT_EQ(format_rounded(512.4), "512");
    // A host that switched to a decimal comma still gets a point.
    if (std::setlocale(LC_NUMERIC, "de_DE.UTF-8") != nullptr) {
        EXPECT_EQ(format_number(2.5), "2.5");
        std::setlocale(LC_NUMERIC, "C");
    }
}

}  // namespace
}  // namespace enteron::scene
