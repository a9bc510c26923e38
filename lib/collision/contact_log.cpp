// SPDX-License-Identifier: Apache-2.0
#include "collision/contact_log.h"

#include <algorithm>

namespace enteron::collision {

void ContactLog::save_state(StateWriter& out) const {
    out.u32(found_);
    out.f64(largest_force_squared_);
    out.u32(largest_force_sphere_);
    out.u32(static_cast<uint32_t>(size_));
    for (const ContactRecord& record : *this) {
        out.f64s(record.point.data(), 3);
        out.f64s(record.normal.data(), 3);
        out.f64s(record.force.data(), 3);
        out.f64(record.depth);
        out.u32(record.sphere);
        out.u32(record.other);
    }
}

void ContactLog::restore_state(StateReader& in, std::size_t spheres, std::size_t others) {
    const uint32_t found = in.u32("contacts found");
    const double largest = in.f64("largest force squared");
    const uint32_t largest_sphere = in.index("sphere of the largest force", spheres);
    const uint32_t size = in.count("contacts recorded", std::min<std::size_t>(records_.size(), found));
    if (!(largest >= 0.0)) in.fail("largest force squared is negative");
    for (uint32_t k = 0; k < size; ++k) {
        ContactRecord record;
        in.f64s("contact point", 3, record.point.data());
        in.f64s("contact normal", 3, record.normal.data());
        in.f64s("contact force", 3, record.force.data());
        record.depth = in.f64("contact depth");
        record.sphere = in.index("contact sphere", spheres);
        record.other = in.index("what the contact touches", others);
        if (!in.checking()) records_[k] = record;
    }
    if (in.checking()) return;
    size_ = size;
    found_ = found;
    largest_force_squared_ = largest;
    largest_force_sphere_ = largest_sphere;
}

}  // namespace enteron::collision
