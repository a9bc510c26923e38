// SPDX-License-Identifier: Apache-2.0
// The tools' mailboxes and channels (lib/collision/tool_mailbox.h, tool_channels.h): a pose
// is taken once, the last post wins, a grasp command is taken once and the last one wins;
// posts from several threads at once never tear a pose (each pose taken is one that some
// thread posted whole); tools added while others post leave the posters' mailboxes valid.
#include <gtest/gtest.h>

#include <atomic>
#include <memory_resource>
#include <thread>
#include <vector>

#include "collision/tool_channels.h"
#include "collision/tool_mailbox.h"

namespace enteron::collision {
namespace {

ToolPose pose(double x, double w = 1.0) {
    ToolPose p;
    p.position = {x, 2.0 * x, -x};
    p.orientation = {w, 0.0, 0.0, 0.0};
    return p;
}

TEST(ToolMailbox, APoseIsTakenOnceAndTheLastPostWins) {
    ToolMailbox mailbox;
    ToolPose taken;
    EXPECT_FALSE(mailbox.take_pose(taken)) << "nothing posted yet";
    mailbox.post_pose(pose(1.0));
    ASSERT_TRUE(mailbox.take_pose(taken));
    EXPECT_EQ(taken.position, pose(1.0).position);
    EXPECT_FALSE(mailbox.take_pose(taken)) << "taken once";
    for (int i = 2; i <= 11; ++i) mailbox.post_pose(pose(i));  // more posts than the ring has slots
    ASSERT_TRUE(mailbox.take_pose(taken));
    EXPECT_EQ(taken.position, pose(11).position);
    EXPECT_EQ(taken.orientation, pose(11).orientation);
    EXPECT_FALSE(mailbox.take_pose(taken));
}

TEST(ToolMailbox, TheLastGraspCommandWinsAndIsTakenOnce) {
    ToolMailbox mailbox;
    EXPECT_EQ(mailbox.take_grasp(), ToolMailbox::Grasp::none);
    mailbox.post_grasp(ToolMailbox::Grasp::grasp);
    mailbox.post_grasp(ToolMailbox::Grasp::release);
    EXPECT_EQ(mailbox.take_grasp(), ToolMailbox::Grasp::release);
    EXPECT_EQ(mailbox.take_grasp(), ToolMailbox::Grasp::none);
    mailbox.post_grasp(ToolMailbox::Grasp::grasp);
    EXPECT_EQ(mailbox.take_grasp(), ToolMailbox::Grasp::grasp);
}

TEST(ToolMailbox, ConcurrentPostsNeverTearAPose) {
    // Three posters write poses whose every value derives from one number; the taker checks
    // that each pose it takes is whole, and that it never goes back to an older post of the
    // same poster (posts of one thread are ordered).
    ToolMailbox mailbox;
    constexpr int kPosters = 3;
    constexpr int kPosts = 20000;
    std::atomic<int> running{kPosters};
    std::vector<std::thread> posters;
    for (int t = 0; t < kPosters; ++t) {
        posters.emplace_back([&, t] {
            for (int i = 1; i <= kPosts; ++i) mailbox.post_pose(pose(1000.0 * t + i, 1.0 + t));
            --running;
        });
    }
    long taken_count = 0, torn = 0, backwards = 0;
    double last[kPosters] = {0.0, 0.0, 0.0};
    ToolPose taken;
    for (;;) {
        // Read before the take: once the posters are done, one more take drains the last post.
        const bool posting = running.load() > 0;
        if (!mailbox.take_pose(taken)) {
            if (posting) continue;
            break;
        }
        ++taken_count;
        const double x = taken.position[0];
        const int t = static_cast<int>(taken.orientation[0] - 1.0 + 0.5);
        if (t < 0 || t >= kPosters || taken.position[1] != 2.0 * x || taken.position[2] != -x ||
            taken.orientation[0] != 1.0 + t || x < 1000.0 * t || x > 1000.0 * t + kPosts) {
            ++torn;
            continue;
        }
        if (x < last[t]) ++backwards;
        last[t] = x;
    }
    for (std::thread& poster : posters) poster.join();
    EXPECT_GT(taken_count, 0);
    EXPECT_EQ(torn, 0);
    EXPECT_EQ(backwards, 0);
}

// A tool added with this radius (mm), to tell them apart.
ToolConfig tool_of_radius(std::size_t millimetres) {
    ToolConfig tool;
    tool.settings.radius = 1e-3 * static_cast<double>(millimetres);
    return tool;
}

TEST(ToolChannels, ToolsAddedWhileOthersPostKeepEveryMailboxValid) {
    ToolChannels channels(std::pmr::new_delete_resource());
    EXPECT_EQ(channels.size(), 0u);
    EXPECT_EQ(channels.mailbox(0), nullptr);
    EXPECT_EQ(channels.added(0), nullptr);
    ASSERT_EQ(channels.add(tool_of_radius(0)), 0u);
    ToolMailbox* first = channels.mailbox(0);
    ASSERT_NE(first, nullptr);

    std::atomic<bool> done{false};
    std::atomic<long> posts{0};
    std::atomic<long> wrong{0};
    std::thread poster([&] {
        for (int i = 1; !done.load(); ++i) {
            // Looked up anew each time, as the C API does, while tools are being added.
            if (ToolMailbox* mailbox = channels.mailbox(0)) mailbox->post_pose(pose(i));
            if (ToolMailbox* last = channels.mailbox(channels.size() - 1)) last->post_grasp(ToolMailbox::Grasp::grasp);
            // What a tool was added with is there as soon as the tool is, and stays.
            const std::size_t newest = channels.size() - 1;
            const ToolConfig* added = channels.added(newest);
            if (added == nullptr || added->settings.radius != 1e-3 * static_cast<double>(newest)) ++wrong;
            ++posts;
        }
    });
    while (posts.load() == 0) std::this_thread::yield();
    for (std::size_t i = 1; i < 200; ++i) EXPECT_EQ(channels.add(tool_of_radius(i)), i);
    const long before = posts.load();
    while (posts.load() == before) std::this_thread::yield();  // it posted after the last add too
    done = true;
    poster.join();
    EXPECT_EQ(channels.size(), 200u);
    EXPECT_EQ(channels.outputs().size(), 200u);
    EXPECT_EQ(channels.mailbox(0), first) << "mailboxes never move";
    EXPECT_EQ(channels.mailbox(200), nullptr);
    EXPECT_EQ(wrong.load(), 0);
    EXPECT_DOUBLE_EQ(channels.added(199)->settings.radius, 0.199);
    ToolPose taken;
    EXPECT_TRUE(first->take_pose(taken));
}

}  // namespace
}  // namespace enteron::collision
