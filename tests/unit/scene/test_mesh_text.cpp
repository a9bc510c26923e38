// SPDX-License-Identifier: Apache-2.0
// A text mesh file read a line and a word at a time (lib/scene/mesh_text.h): lines counted
// from the first line given, any line end (\n, \r\n, none at the end), words split on
// spaces and tabs, a comment ending its line; numbers read as strtod reads them (a leading
// '+' too) and refused with the line when they are not numbers, not finite, or out of a
// range; bytes that are not text shown escaped.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "base/error.h"
#include "refusal.h"
#include "scene/mesh_text.h"

namespace enteron::scene {
namespace {

using unit_test::refusal;

TEST(MeshText, LinesAndWordsAndComments) {
    MeshText in("v 1 2\r\n\n\tf  1\t2 # three\nlast", 5, '#');
    ASSERT_TRUE(in.next_line());
    EXPECT_EQ(in.line(), 5u);
    EXPECT_EQ(in.word(), "v");
    EXPECT_FALSE(in.at_end());
    EXPECT_EQ(in.word(), "1");
    EXPECT_EQ(in.word(), "2");
    EXPECT_TRUE(in.at_end()) << "the \\r is a space";
    EXPECT_EQ(in.word(), "");
    ASSERT_TRUE(in.next_line());
    EXPECT_TRUE(in.at_end());
    ASSERT_TRUE(in.next_line());
    EXPECT_EQ(in.line(), 7u);
    EXPECT_EQ(in.word(), "f");
    EXPECT_EQ(in.word(), "1");
    EXPECT_EQ(in.word(), "2");
    EXPECT_EQ(in.word(), "") << "the comment ends the line";
    ASSERT_TRUE(in.next_line());
    EXPECT_EQ(in.word(), "last");
    EXPECT_EQ(in.consumed(), std::string("v 1 2\r\n\n\tf  1\t2 # three\nlast").size());
    EXPECT_FALSE(in.next_line());
    MeshText no_comment("a # b");
    ASSERT_TRUE(no_comment.next_line());
    no_comment.word();
    EXPECT_EQ(no_comment.word(), "#") << "without a comment character '#' is a word";
}

TEST(MeshText, NumbersAreReadAsStrtodReadsThemOrRefusedWithTheLine) {
    MeshText in("0.1 +2.5e-3 -7 1e-310 3.0000000000000004 12\nx nan 1e999 4.5 99 -1", 1);
    ASSERT_TRUE(in.next_line());
    for (const char* text : {"0.1", "+2.5e-3", "-7", "1e-310", "3.0000000000000004"})
        EXPECT_EQ(in.number("x"), std::strtod(text, nullptr)) << text;
    EXPECT_EQ(in.number<float>("x"), 12.0f);
    ASSERT_TRUE(in.next_line());
    EXPECT_EQ(refusal([&] { in.number("the vertex's x"); }), "line 2: expected the vertex's x, a finite number, found \"x\"");
    EXPECT_EQ(refusal([&] { in.number("y"); }), "line 2: expected y, a finite number, found \"nan\"");
    EXPECT_EQ(refusal([&] { in.number("z"); }), "line 2: expected z, a finite number, found \"1e999\"");
    EXPECT_EQ(refusal([&] { in.integer("a count", 0, 10); }), "line 2: expected a count, a whole number, found \"4.5\"");
    EXPECT_EQ(refusal([&] { in.integer("a count", 0, 10); }), "line 2: a count is 99, not in [0, 10]");
    EXPECT_EQ(in.integer("an index", -5, 5), -1);
    EXPECT_EQ(refusal([&] { in.number("w"); }), "line 2: expected w, found the end of the line");
}

TEST(MeshText, BytesThatAreNotTextAreShownEscaped) {
    EXPECT_EQ(MeshText::shown("abc"), "\"abc\"");
    EXPECT_EQ(MeshText::shown(std::string("a\x01\"\\\xff", 5)), "\"a\\x01\\x22\\x5c\\xff\"");
    EXPECT_EQ(MeshText::shown(std::string(50, 'y')), "\"" + std::string(40, 'y') + "...\"");
}

}  // namespace
}  // namespace enteron::scene
