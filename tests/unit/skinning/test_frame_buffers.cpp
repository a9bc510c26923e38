// SPDX-License-Identifier: Apache-2.0
// Work buffers that breathe (lib/skinning/frame_buffers.h): a buffer resized keeps room
// for half as much again, so sizes that come and go within a third of the largest seen
// never reallocate; assign fills every element.
#include <gtest/gtest.h>

#include <vector>

#include "skinning/frame_buffers.h"

namespace enteron::skinning {
namespace {

TEST(FrameBuffers, SizesThatBreatheDoNotReallocate) {
    std::vector<double> buffer;
    resize_buffer(buffer, 900);
    EXPECT_EQ(buffer.size(), 900u);
    EXPECT_GE(buffer.capacity(), 1350u) << "half as much again";
    const double* data = buffer.data();
    for (std::size_t size : {1000u, 700u, 1100u, 1200u, 300u, 1000u}) {
        resize_buffer(buffer, size);
        ASSERT_EQ(buffer.data(), data) << "size " << size;
    }
    resize_buffer(buffer, 5000);
    EXPECT_NE(buffer.data(), data) << "grown beyond: it reallocates, with headroom again";
    EXPECT_GE(buffer.capacity(), 7500u);
    assign_buffer(buffer, 10, 2.5);
    EXPECT_EQ(buffer, std::vector<double>(10, 2.5));
}

}  // namespace
}  // namespace enteron::skinning
