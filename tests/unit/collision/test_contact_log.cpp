// SPDX-License-Identifier: Apache-2.0
// A contact effect's log (lib/collision/contact_log.h): records up to its capacity and
// counts the rest; the largest force is tracked over every contact, recorded or not; clear
// forgets an evaluation; a saved log restores to the same records and a damaged one (a
// sphere or an obstacle that does not exist, more records than found, a non-finite value)
// is refused with the log unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/saved_image.h"
#include "collision/contact_log.h"

namespace enteron::collision {
namespace {

std::pmr::memory_resource* const kMemory = std::pmr::new_delete_resource();

TEST(ContactLog, RecordsUpToItsCapacityAndCountsTheRest) {
    ContactLog log(ContactKind::obstacle, 2, kMemory);
    EXPECT_EQ(log.kind(), ContactKind::obstacle);
    log.add(4, 0, 0.001, Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, 1.0));
    log.add(5, 0, 0.002, Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, 2.0));
    log.add(9, 1, 0.004, Vec3(2, 0, 0), Vec3(0, 0, 1), Vec3(0, 3.0, 0));  // beyond the capacity
    EXPECT_EQ(log.size(), 2u);
    EXPECT_EQ(log.found(), 3u);
    EXPECT_EQ(log.largest_force_squared(), 9.0) << "over every contact, recorded or not";
    EXPECT_EQ(log.largest_force_sphere(), 9u);
    EXPECT_EQ(log.begin()[1].sphere, 5u);
    EXPECT_EQ(log.begin()[1].depth, 0.002);
    log.clear();
    EXPECT_EQ(log.size(), 0u);
    EXPECT_EQ(log.found(), 0u);
    EXPECT_EQ(log.largest_force_squared(), 0.0);
    EXPECT_EQ(log.capacity(), 2u);
}

std::vector<unsigned char> saved(const ContactLog& log) {
    return state_test::saved_image([&](StateWriter& out) {
        out.begin_section("log", 1);
        log.save_state(out);
        out.end_section();
    });
}

// Restores `bytes` into `log` (both passes); the refusal's message, or "".
std::string restore(ContactLog& log, const std::vector<unsigned char>& bytes, std::size_t spheres, std::size_t others) {
    try {
        StateReader in(bytes.data(), bytes.size());
        for (int pass = 0; pass < 2; ++pass) {
            in.begin_section("log", 1);
            log.restore_state(in, spheres, others);
            in.end_section();
            if (pass == 0) in.start_applying();
        }
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

TEST(ContactLog, ASavedLogRestoresAndADamagedOneIsRefused) {
    ContactLog log(ContactKind::tool, 4, kMemory);
    log.add(3, 1, 0.001, Vec3(0.1, 0.2, 0.3), Vec3(0, 1, 0), Vec3(0.5, 0, 0));
    log.add(7, 0, 0.002, Vec3(0.4, 0.5, 0.6), Vec3(1, 0, 0), Vec3(0, 0, -2.0));
    const std::vector<unsigned char> bytes = saved(log);
    ContactLog restored(ContactKind::tool, 4, kMemory);
    EXPECT_EQ(restore(restored, bytes, 8, 2), "");
    EXPECT_EQ(saved(restored), bytes);
    EXPECT_EQ(restored.begin()[1].force, Vec3(0, 0, -2.0));

    ContactLog untouched(ContactKind::tool, 4, kMemory);
    untouched.add(0, 0, 0.003, Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitZ());
    EXPECT_EQ(restore(untouched, bytes, 7, 2), "state: section 'log': sphere of the largest force is 7, not below 7");
    EXPECT_EQ(restore(untouched, bytes, 8, 1), "state: section 'log': what the contact touches is 1, not below 1");
    ContactLog small(ContactKind::tool, 1, kMemory);
    EXPECT_EQ(restore(small, bytes, 8, 2), "state: section 'log': contacts recorded is 2, more than 1");
    ContactLog nan(ContactKind::tool, 4, kMemory);
    nan.add(1, 0, std::nan(""), Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitZ());
    EXPECT_EQ(restore(untouched, saved(nan), 8, 2), "state: section 'log': contact depth is nan, not a finite number");
    EXPECT_EQ(untouched.size(), 1u);
    EXPECT_EQ(untouched.begin()[0].depth, 0.003) << "nothing of a refused log is kept";
}

}  // namespace
}  // namespace enteron::collision
