// SPDX-License-Identifier: Apache-2.0
// The published state of a scene: an immutable copy made after each step, read by any
// number of threads (queries, skins, the LCM bridge) while the stepping thread goes on.
//
// A small pool of preallocated slots: the stepping thread fills a slot that is neither the
// latest nor being read, then makes it the latest; a reader pins the latest slot while it
// copies from it. The bookkeeping is atomic, without a lock: the stepping thread never
// waits (nor makes a system call) for a reader, and readers never wait for it. A reader
// counts itself on the latest slot, then checks that the slot is still the latest (else it
// uncounts and tries again): the writer only fills slots that are not the latest and that
// it saw unread, so a slot a reader counted on and found latest is complete and stays put.
//
// The publisher outlives the scene when skins still read it (the C API shares it between
// them): a skin then keeps working on the last state published.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "collision/contact_log.h"
#include "collision/tool.h"
#include "mechanics/effect_id.h"
#include "mechanics/rigid_frames.h"
#include "mechanics/step_work.h"
#include "spline/catmull_rom.h"

namespace enteron::scene {

struct SceneStats {
    double time = 0.0;            // s
    uint64_t steps = 0;
    uint64_t substeps = 0;
    uint64_t rollbacks = 0;
    double kinetic_energy = 0.0;  // J
    double potential_energy = 0.0;
    uint32_t contacts = 0;
    double max_penetration = 0.0;  // m
    uint64_t last_step_ns = 0;
    double rest_length = 0.0;  // m, of the axis (constant)
    // What the last step did (every attempt) and the slow paths so far (ent_stats): the
    // stepper's counts (mechanics::StepCounters) and the effects' (Effect::add_work).
    uint32_t last_step_attempts = 0;
    uint32_t last_step_substeps = 0;
    uint64_t max_step_ns = 0;
    uint64_t late_steps = 0;        // wall time over the dt they simulated
    uint64_t subdivided_steps = 0;  // accepted after more than one attempt
    mechanics::StepWork work;
};

// The contacts of the last evaluation, as the scene published them.
struct ContactTotals {
    // By ContactKind: found in the evaluation, and listed in Snapshot::contacts, which holds
    // the tools' first, then the obstacles', then the self-contacts', up to its capacity.
    std::array<uint32_t, collision::kContactKinds> found{};
    std::array<uint32_t, collision::kContactKinds> listed{};
    double largest_force = 0.0;         // N, of every contact found
    uint32_t largest_force_sphere = 0;  // where
    uint32_t spheres = 0;               // collision spheres (0: none): sphere i is at u = i / (spheres - 1)
};

struct EffectStats {
    bool enabled = false;
    uint64_t calls = 0;
    uint64_t total_time_ns = 0;
};

// Where an obstacle rests in a published state.
struct ObstacleOutput {
    bool present = false;  // false once removed
    mechanics::RigidPose pose;
};

struct Snapshot {
    explicit Snapshot(std::pmr::memory_resource* memory)
        : control_points(memory), tools(memory), obstacles(memory), contacts(memory) {}
    std::pmr::vector<double> control_points;  // x y z per point, m
    SceneStats stats;
    std::array<EffectStats, mechanics::kEffectCount> effects{};
    std::pmr::vector<collision::ToolOutput> tools;  // by tool index
    std::pmr::vector<ObstacleOutput> obstacles;     // by obstacle index
    std::pmr::vector<collision::ContactRecord> contacts;  // see ContactTotals
    ContactTotals contact_totals;
};

// One tube of the published axis (mechanics/axis_model.h): its control points are
// [first, first + control_points) of every snapshot's, its spline continues past its ends so.
struct PublishedTube {
    std::size_t first = 0;
    std::size_t control_points = 0;
    spline::Ends ends;
};

class SnapshotPublisher {
public:
    static constexpr std::size_t kSlots = 8;

    // `ends`: how the axis' spline continues past its ends (scene_config.h spline_ends), for
    // the readers that evaluate the axis from the control points. One tube: every point.
    SnapshotPublisher(std::size_t coordinates, std::pmr::memory_resource* memory, spline::Ends ends = {});
    // Several tubes, back to back in `coordinates` (3 per point), at least one.
    SnapshotPublisher(std::size_t coordinates, const std::vector<PublishedTube>& tubes,
                      std::pmr::memory_resource* memory);

    // A slot the stepping thread may fill, or nullptr if every slot is busy (then this
    // publication is skipped; the next one will go through).
    Snapshot* begin_write();
    // Makes the slot from begin_write the latest.
    void publish(Snapshot* slot);

    // Makes room for `count` tools in every slot, so that filling one never allocates.
    // Allocates; waits for the readers of a slot to finish their copy. Not during a step.
    void reserve_tools(std::size_t count);
    // Makes room for `count` contact records in every slot, likewise.
    void reserve_contacts(std::size_t count);
    // The same for `count` obstacles.
    void reserve_obstacles(std::size_t count);
    // Control points of every snapshot.
    std::size_t control_points() const { return slots_.front().control_points.size() / 3; }
    // The spline's end treatment of every snapshot's axis: of its first tube.
    spline::Ends ends() const { return tubes_.front().ends; }
    // The tubes of every snapshot's axis (at least one), in the order of their points.
    std::size_t tube_count() const { return tubes_.size(); }
    const PublishedTube& tube(std::size_t index) const { return tubes_[index]; }

    // Pins the latest snapshot for reading while it lives.
    class Reader {
    public:
        Reader(const SnapshotPublisher& publisher);
        ~Reader();
        Reader(const Reader&) = delete;
        Reader& operator=(const Reader&) = delete;
        const Snapshot& operator*() const { return *snapshot_; }
        const Snapshot* operator->() const { return snapshot_; }

    private:
        const SnapshotPublisher& publisher_;
        std::size_t slot_;
        const Snapshot* snapshot_;
    };

private:
    // Runs reserve(slot) on every slot by the rules of begin_write (reserve_tools).
    template <class Reserve>
    void reserve_each(Reserve&& reserve);

    std::pmr::vector<Snapshot> slots_;
    mutable std::array<std::atomic<uint32_t>, kSlots> readers_{};  // readers pinning each slot
    std::atomic<std::size_t> latest_{0};
    std::pmr::vector<PublishedTube> tubes_;
};

}  // namespace enteron::scene
