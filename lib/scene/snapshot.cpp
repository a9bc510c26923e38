#include "scene/snapshot.h"

#include <thread>

namespace enteron::scene {

SnapshotPublisher::SnapshotPublisher(std::size_t coordinates, std::pmr::memory_resource* memory)
    : slots_(memory) {
    slots_.reserve(kSlots);
    for (std::size_t i = 0; i < kSlots; ++i) {
        slots_.emplace_back(memory);
        slots_.back().control_points.assign(coordinates, 0.0);
    }
}

Snapshot* SnapshotPublisher::begin_write() {
    std::lock_guard<std::mutex> lock(mutex_);
    // The slot published before the latest, if no one reads it: the stepping thread then
    // writes into two slots in turn, which stay in its cache (the contact list of a pile is
    // tens of kilobytes).
    if (previous_ != latest_ && readers_[previous_] == 0) return &slots_[previous_];
    for (std::size_t i = 1; i < kSlots; ++i) {
        const std::size_t slot = (latest_ + i) % kSlots;
        if (readers_[slot] == 0) return &slots_[slot];
    }
    return nullptr;
}

void SnapshotPublisher::publish(Snapshot* slot) {
    std::lock_guard<std::mutex> lock(mutex_);
    previous_ = latest_;
    latest_ = static_cast<std::size_t>(slot - slots_.data());
}

template <class Change>
void SnapshotPublisher::change_each_slot(Change&& change) {
    for (std::size_t slot = 0; slot < kSlots; ++slot) {
        for (;;) {
            {
                std::lock_guard<std::mutex> lock(mutex_);
                if (readers_[slot] == 0) {
                    change(slots_[slot]);
                    break;
                }
            }
            std::this_thread::yield();  // a reader is copying: microseconds
        }
    }
}

void SnapshotPublisher::reserve_tools(std::size_t count) {
    change_each_slot([count](Snapshot& slot) { slot.tools.reserve(count); });
}

void SnapshotPublisher::reserve_contacts(std::size_t count) {
    change_each_slot([count](Snapshot& slot) { slot.contacts.reserve(count); });
}

SnapshotPublisher::Reader::Reader(const SnapshotPublisher& publisher) : publisher_(publisher) {
    std::lock_guard<std::mutex> lock(publisher.mutex_);
    slot_ = publisher.latest_;
    publisher.readers_[slot_] += 1;
    snapshot_ = &publisher.slots_[slot_];
}

SnapshotPublisher::Reader::~Reader() {
    std::lock_guard<std::mutex> lock(publisher_.mutex_);
    publisher_.readers_[slot_] -= 1;
}

}  // namespace enteron::scene
