#include "scene/snapshot.h"

namespace enteron::scene {

SnapshotPublisher::SnapshotPublisher(std::size_t coordinates, std::pmr::memory_resource* memory)
    : slots_(memory) {
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
