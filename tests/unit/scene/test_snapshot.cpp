// SPDX-License-Identifier: Apache-2.0
// The snapshot publisher (lib/scene/snapshot.h): readers see the latest published state and
// keep the slot they pinned unchanged while they read it; the writer never fills a pinned
// slot (it skips a publication when every other slot is pinned); and a reader on another
// thread never sees a half-written snapshot.
#include "scene/snapshot.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <memory>
#include <memory_resource>
#include <thread>
#include <vector>

namespace {

using enteron::scene::Snapshot;
using enteron::scene::SnapshotPublisher;

constexpr std::size_t kCoordinates = 12;

// Fills a free slot with `value` in every control point coordinate and at stats.time, then
// publishes it; false if every slot but the latest is pinned.
bool publish(SnapshotPublisher& publisher, double value) {
    Snapshot* slot = publisher.begin_write();
    if (slot == nullptr) return false;
    for (double& x : slot->control_points) x = value;
    slot->stats.time = value;
    publisher.publish(slot);
    return true;
}

// True if every value of the snapshot is `value`.
bool holds(const Snapshot& snapshot, double value) {
    for (double x : snapshot.control_points)
        if (x != value) return false;
    return snapshot.stats.time == value;
}

TEST(SnapshotPublisher, AReaderSeesTheLatestPublication) {
    SnapshotPublisher publisher(kCoordinates, std::pmr::new_delete_resource());
    for (int k = 1; k <= 20; ++k) {
        ASSERT_TRUE(publish(publisher, k));
        const SnapshotPublisher::Reader reader(publisher);
        EXPECT_TRUE(holds(*reader, k)) << k;
        EXPECT_EQ(reader->control_points.size(), kCoordinates);
    }
}

TEST(SnapshotPublisher, APinnedSlotStaysUnchangedWhileLaterStatesArePublished) {
    SnapshotPublisher publisher(kCoordinates, std::pmr::new_delete_resource());
    ASSERT_TRUE(publish(publisher, 1.0));
    const SnapshotPublisher::Reader pinned(publisher);
    for (int k = 2; k <= 50; ++k) {
        ASSERT_TRUE(publish(publisher, k));  // one pinned slot leaves others to write
        ASSERT_TRUE(holds(*pinned, 1.0)) << "publication " << k << " wrote into the pinned slot";
    }
    const SnapshotPublisher::Reader latest(publisher);
    EXPECT_TRUE(holds(*latest, 50.0));
}

TEST(SnapshotPublisher, EverySlotPinnedSkipsThePublicationUntilAReaderLetsGo) {
    SnapshotPublisher publisher(kCoordinates, std::pmr::new_delete_resource());
    // Pin each slot in turn: publish, then read (the reader pins the latest).
    std::vector<std::unique_ptr<SnapshotPublisher::Reader>> readers;
    for (std::size_t k = 1; k < SnapshotPublisher::kSlots; ++k) {
        ASSERT_TRUE(publish(publisher, double(k))) << k;
        readers.push_back(std::make_unique<SnapshotPublisher::Reader>(publisher));
    }
    // The first slot (where the initial state was) is free: one more publication.
    readers.insert(readers.begin(), nullptr);
    ASSERT_TRUE(publish(publisher, 100.0));
    readers.front() = std::make_unique<SnapshotPublisher::Reader>(publisher);
    // Every slot is pinned now: the writer gets none, and the latest state stays readable.
    EXPECT_EQ(publisher.begin_write(), nullptr);
    EXPECT_FALSE(publish(publisher, 101.0));
    {
        const SnapshotPublisher::Reader reader(publisher);
        EXPECT_TRUE(holds(*reader, 100.0));
    }
    for (std::size_t k = 1; k < readers.size(); ++k) EXPECT_TRUE(holds(**readers[k], double(k)));
    // A reader that lets go frees its slot for the next publication.
    readers[1].reset();
    ASSERT_TRUE(publish(publisher, 102.0));
    const SnapshotPublisher::Reader reader(publisher);
    EXPECT_TRUE(holds(*reader, 102.0));
}

TEST(SnapshotPublisher, ReadersOnOtherThreadsNeverSeeAHalfWrittenSnapshot) {
    SnapshotPublisher publisher(kCoordinates, std::pmr::new_delete_resource());
    std::atomic<bool> done{false};
    std::atomic<int> torn{0}, backwards{0};
    std::vector<std::thread> readers;
    for (int r = 0; r < 2; ++r)
        readers.emplace_back([&] {
            double last = 0.0;
            while (!done.load(std::memory_order_acquire)) {
                const SnapshotPublisher::Reader reader(publisher);
                const double value = reader->stats.time;
                if (!holds(*reader, value)) torn.fetch_add(1);
                if (value < last) backwards.fetch_add(1);
                last = value;
            }
        });
    int published = 0;
    for (int k = 1; k <= 20000; ++k) published += publish(publisher, k) ? 1 : 0;
    done.store(true, std::memory_order_release);
    for (std::thread& t : readers) t.join();
    EXPECT_EQ(torn.load(), 0);
    EXPECT_EQ(backwards.load(), 0) << "a reader saw an older state after a newer one";
    EXPECT_GT(published, 0);
}

}  // namespace
