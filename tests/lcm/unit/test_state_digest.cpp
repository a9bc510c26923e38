// SPDX-License-Identifier: Apache-2.0
// The state digest (state_digest.h): a change of any one bit of any one value it covers
// (control points, time, the tools' pose and grasp action) changes it; so do the order and
// the count of the values.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "lcm/state_digest.h"

namespace enteron::lcm {
namespace {

void flip(double& value, int bit) {
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    bits ^= uint64_t{1} << bit;
    std::memcpy(&value, &bits, sizeof bits);
}

TEST(StateDigest, AnyOneBitOfAnyValueChangesIt) {
    std::vector<double> points(3 * 17), tools(kToolDigestValues * 2);
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = 0.01 * static_cast<double>(i) - 0.2;
    for (std::size_t i = 0; i < tools.size(); ++i) tools[i] = 0.5 - 0.125 * static_cast<double>(i);
    const double time_s = 1.234;
    const int64_t reference = tick_digest(points.data(), points.size(), time_s, tools.data(), tools.size());
    EXPECT_EQ(tick_digest(points.data(), points.size(), time_s, tools.data(), tools.size()), reference);
    for (int bit = 0; bit < 64; ++bit) {
        for (std::size_t i = 0; i < points.size(); ++i) {
            std::vector<double> changed = points;
            flip(changed[i], bit);
            ASSERT_NE(tick_digest(changed.data(), changed.size(), time_s, tools.data(), tools.size()), reference)
                << "point value " << i << " bit " << bit;
        }
        for (std::size_t i = 0; i < tools.size(); ++i) {
            std::vector<double> changed = tools;
            flip(changed[i], bit);
            ASSERT_NE(tick_digest(points.data(), points.size(), time_s, changed.data(), changed.size()), reference)
                << "tool value " << i << " bit " << bit;
        }
        double changed_time = time_s;
        flip(changed_time, bit);
        ASSERT_NE(tick_digest(points.data(), points.size(), changed_time, tools.data(), tools.size()), reference);
    }
}

TEST(StateDigest, DependsOnOrderAndCount) {
    const double a[] = {1.0, 2.0, 3.0, 4.0, 5.0};
    const double b[] = {2.0, 1.0, 3.0, 4.0, 5.0};
    const double c[] = {1.0, 2.0, 3.0, 4.0, 5.0, 0.0};
    EXPECT_NE(tick_digest(a, 5, 0.0, nullptr, 0), tick_digest(b, 5, 0.0, nullptr, 0));
    EXPECT_NE(tick_digest(a, 5, 0.0, nullptr, 0), tick_digest(c, 6, 0.0, nullptr, 0));
    EXPECT_NE(tick_digest(a, 4, 0.0, nullptr, 0), tick_digest(a, 5, 0.0, nullptr, 0));
}

}  // namespace
}  // namespace enteron::lcm
