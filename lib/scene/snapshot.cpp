// SPDX-License-Identifier: Apache-2.0
#include "scene/snapshot.h"

#include <algorithm>
#include <thread>

namespace enteron::scene {

SnapshotPublisher::SnapshotPublisher(std::size_t coordinates, std::pmr::memory_resource* memory, spline::Ends ends)
    : SnapshotPublisher(coordinates, {PublishedTube{0, coordinates / 3, ends}}, memory) {}

SnapshotPublisher::SnapshotPublisher(std::size_t coordinates, const std::vector<PublishedTube>& tubes,
                                     std::pmr::memory_resource* memory)
    : slots_(memory), tubes_(tubes.begin(), tubes.end(), memory) {
    slots_.reserve(kSlots);
    for (std::size_t i = 0; i < kSlots; ++i) {
        slots_.emplace_back(memory);
        slots_.back().control_points.assign(coordinates, 0.0);
    }
}

// The stepping thread alone writes latest_ (relaxed loads of it here are its own stores).
// Sequentially consistent everywhere else: the argument in snapshot.h needs one order of
// the writer's "unread?" check, the readers' counts and the publications.
Snapshot* SnapshotPublisher::begin_write() {
    const std::size_t latest = latest_.load(std::memory_order_relaxed);
    for (std::size_t i = 1; i < kSlots; ++i) {
        const std::size_t slot = (latest + i) % kSlots;
        if (readers_[slot].load() == 0) return &slots_[slot];
    }
    return nullptr;
}

void SnapshotPublisher::publish(Snapshot* slot) { latest_.store(static_cast<std::size_t>(slot - slots_.data())); }

// The stepping thread's own rules (begin_write) say when it may touch a slot: not the
// latest, and unread. So each other slot is reserved once its readers are gone; then the
// latest is copied into a reserved slot, that one is published, and the old latest is
// reserved once its last reader is gone (no new reader pins a slot that is not the latest).
template <class Reserve>
void SnapshotPublisher::reserve_each(Reserve&& reserve) {
    const auto wait_unread = [this](std::size_t slot) {
        while (readers_[slot].load() != 0) std::this_thread::yield();  // a reader is copying: microseconds
    };
    const std::size_t old_latest = latest_.load(std::memory_order_relaxed);
    for (std::size_t slot = 0; slot < kSlots; ++slot) {
        if (slot == old_latest) continue;
        wait_unread(slot);
        reserve(slots_[slot]);
    }
    // The same state in another slot, within the capacities it has: values only, never a
    // vector's own fields (control_points() reads those from any thread).
    Snapshot& moved = slots_[(old_latest + 1) % kSlots];
    const Snapshot& latest = slots_[old_latest];
    std::copy(latest.control_points.begin(), latest.control_points.end(), moved.control_points.begin());
    moved.stats = latest.stats;
    moved.effects = latest.effects;
    moved.tools.assign(latest.tools.begin(), latest.tools.end());
    moved.obstacles.assign(latest.obstacles.begin(), latest.obstacles.end());
    moved.contacts.assign(latest.contacts.begin(), latest.contacts.end());
    moved.contact_totals = latest.contact_totals;
    publish(&moved);
    wait_unread(old_latest);
    reserve(slots_[old_latest]);
}

void SnapshotPublisher::reserve_tools(std::size_t count) {
    reserve_each([&](Snapshot& slot) { slot.tools.reserve(count); });
}

void SnapshotPublisher::reserve_contacts(std::size_t count) {
    reserve_each([&](Snapshot& slot) { slot.contacts.reserve(count); });
}

void SnapshotPublisher::reserve_obstacles(std::size_t count) {
    reserve_each([&](Snapshot& slot) { slot.obstacles.reserve(count); });
}

SnapshotPublisher::Reader::Reader(const SnapshotPublisher& publisher) : publisher_(publisher) {
    for (;;) {
        slot_ = publisher.latest_.load();
        publisher.readers_[slot_].fetch_add(1);
        if (publisher.latest_.load() == slot_) break;
        publisher.readers_[slot_].fetch_sub(1);  // a newer one came meanwhile: take that
    }
    snapshot_ = &publisher.slots_[slot_];
}

SnapshotPublisher::Reader::~Reader() { publisher_.readers_[slot_].fetch_sub(1); }

}  // namespace enteron::scene
