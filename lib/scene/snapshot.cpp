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
    for (std::size_t i = 1; i < kSlots; ++i) {
        const std::size_t slot = (latest_ + i) % kSlots;
        if (readers_[slot] == 0) return &slots_[slot];
    }
    return nullptr;
}

void SnapshotPublisher::publish(Snapshot* slot) {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = static_cast<std::size_t>(slot - slots_.data());
}

template <class Reserve>
void SnapshotPublisher::reserve_each(Reserve&& reserve) {
    for (std::size_t slot = 0; slot < kSlots; ++slot) {
        for (;;) {
            {
                std::lock_guard<std::mutex> lock(mutex_);
                if (readers_[slot] == 0) {
                    reserve(slots_[slot]);
                    break;
                }
            }
            std::this_thread::yield();  // a reader is copying: microseconds
        }
    }
}

void SnapshotPublisher::reserve_tools(std::size_t count) {
    reserve_each([&](Snapshot& slot) { slot.tools.reserve(count); });
}

void SnapshotPublisher::reserve_obstacles(std::size_t count) {
    reserve_each([&](Snapshot& slot) { slot.obstacles.reserve(count); });
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
