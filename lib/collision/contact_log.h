// SPDX-License-Identifier: Apache-2.0
// What the contacts of the bowel did in an evaluation, one record each, for the published
// contact list (ent_scene_contacts): a trainer scores which part of the bowel a tool
// touched, how hard and for how long.
//
// Each contact effect (self-contact, environment, tools) owns one log, clears it at the
// start of every evaluation and adds its contacts as it computes their forces, so after a
// step each log holds the contacts of the step's last evaluation: the same evaluation whose
// forces moved the bowel and whose tool wrench the haptic device renders. The scene copies
// the logs into the snapshot it publishes.
//
// Bounded: the records live in an array sized once (no step allocates); contacts beyond
// its capacity are counted but not recorded. The largest force is tracked over every
// contact, recorded or not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "base/state_io.h"

namespace enteron::collision {

// The numbers are those of ENT_CONTACT_* in enteron.h.
enum class ContactKind : int32_t { self = 0, obstacle = 1, tool = 2 };
inline constexpr std::size_t kContactKinds = 3;

// Each log, and the published list, holds up to this many contacts per collision sphere: a
// dense pile makes one or two (the collision bench's: 788 for 960 spheres).
inline constexpr std::size_t kLoggedContactsPerSphere = 4;

struct ContactRecord {
    Vec3 point = Vec3::Zero();   // m: on the obstacle's or the tool's surface; self-contact: midway between the centres
    Vec3 normal = Vec3::Zero();  // unit, pushing the bowel at `sphere` away from what it touches
    Vec3 force = Vec3::Zero();   // N, on the bowel at `sphere` (self-contact: `other` gets minus it)
    double depth = 0.0;          // m, > 0
    uint32_t sphere = 0;         // the bowel's collision sphere
    uint32_t other = 0;          // self-contact: the other sphere; obstacle: its index; tool: its index
};

class ContactLog {
public:
    ContactLog(ContactKind kind, std::size_t capacity, std::pmr::memory_resource* memory)
        : kind_(kind), records_(capacity, ContactRecord{}, memory) {}

    ContactKind kind() const { return kind_; }

    // Forgets the last evaluation's contacts.
    void clear() {
        size_ = 0;
        found_ = 0;
        largest_force_squared_ = 0.0;
        largest_force_sphere_ = 0;
    }

    void add(uint32_t sphere, uint32_t other, double depth, const Vec3& point, const Vec3& normal,
             const Vec3& force) {
        found_ += 1;
        const double force_squared = force.squaredNorm();
        if (force_squared > largest_force_squared_) {
            largest_force_squared_ = force_squared;
            largest_force_sphere_ = sphere;
        }
        if (size_ == records_.size()) return;  // full: counted, not recorded
        ContactRecord& record = records_[size_++];
        record.point = point;
        record.normal = normal;
        record.force = force;
        record.depth = depth;
        record.sphere = sphere;
        record.other = other;
    }

    // The recorded contacts: the first size() of those found.
    const ContactRecord* begin() const { return records_.data(); }
    const ContactRecord* end() const { return records_.data() + size_; }
    std::size_t size() const { return size_; }
    std::size_t capacity() const { return records_.size(); }
    // Contacts found in the last evaluation, recorded or not.
    uint32_t found() const { return found_; }
    // The largest |force| among them (N), and its sphere.
    double largest_force_squared() const { return largest_force_squared_; }
    uint32_t largest_force_sphere() const { return largest_force_sphere_; }

    // Save and restore (state_io.h): the records, the count found and the largest force, so
    // that a restored scene publishes the contacts the saved one did. Restore checks that the
    // records fit, name spheres below `spheres` and others below `others`, and are finite.
    void save_state(StateWriter& out) const;
    void restore_state(StateReader& in, std::size_t spheres, std::size_t others);

private:
    ContactKind kind_;
    std::pmr::vector<ContactRecord> records_;  // sized once: the capacity
    std::size_t size_ = 0;
    uint32_t found_ = 0;
    double largest_force_squared_ = 0.0;
    uint32_t largest_force_sphere_ = 0;
};

}  // namespace enteron::collision
