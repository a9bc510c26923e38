// SPDX-License-Identifier: Apache-2.0
// The control points a pinned span holds (lib/scene/pin_spans.h): those whose rest arc
// length i L / (n - 1) lies in [from, to], a span ending on a point holding it, one between
// two points holding none.
#include "scene/pin_spans.h"

#include <gtest/gtest.h>

namespace enteron::scene {
namespace {

// 11 control points over 1 m: one every 0.1 m.
ControlPointRange span_of(double from, double to) { return control_points_in(PinSpan{from, to, {}}, 11, 1.0); }

TEST(PinSpans, ASpanHoldsTheControlPointsWithinIt) {
    const ControlPointRange middle = span_of(0.25, 0.55);
    EXPECT_EQ(middle.first, 3u);
    EXPECT_EQ(middle.last, 5u);
    // Ends on points (0.3 and 0.7 are not exact multiples of 0.1 in binary): both held.
    const ControlPointRange on_points = span_of(0.3, 0.7);
    EXPECT_EQ(on_points.first, 3u);
    EXPECT_EQ(on_points.last, 7u);
    const ControlPointRange whole = span_of(0.0, 1.0);
    EXPECT_EQ(whole.first, 0u);
    EXPECT_EQ(whole.last, 10u);
    const ControlPointRange one = span_of(0.4, 0.4);
    EXPECT_EQ(one.first, 4u);
    EXPECT_EQ(one.last, 4u);
}

TEST(PinSpans, ASpanBetweenTwoPointsHoldsNone) {
    EXPECT_TRUE(span_of(0.31, 0.39).empty());
    EXPECT_FALSE(span_of(0.31, 0.4).empty());
}

}  // namespace
}  // namespace enteron::scene
