// SPDX-License-Identifier: Apache-2.0
// The frame-to-frame hash map (lib/skinning/index_hash.h): a key inserted is found with its
// value, a second insert keeps the first value, a missing key says so; it grows past its
// room without losing entries; clear forgets them and keeps its memory.
#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

#include "skinning/index_hash.h"

namespace enteron::skinning {
namespace {

TEST(IndexHash, FindsWhatWasInsertedAndGrowsWithoutLosingIt) {
    IndexHash hash;
    hash.clear(4);
    std::mt19937_64 random(3);
    std::unordered_map<uint64_t, uint32_t> reference;
    for (uint32_t i = 0; i < 5000; ++i) {
        const uint64_t key = random() % 20000;  // repeats on purpose
        bool inserted = false;
        const uint32_t value = hash.find_or_insert(key, i, &inserted);
        const auto [at, fresh] = reference.emplace(key, i);
        ASSERT_EQ(inserted, fresh) << key;
        ASSERT_EQ(value, at->second) << "an existing key keeps its first value";
    }
    for (const auto& [key, value] : reference) ASSERT_EQ(hash.find(key), value);
    EXPECT_EQ(hash.find(20001), IndexHash::kMissing);
    hash.clear(10);
    EXPECT_EQ(hash.find(reference.begin()->first), IndexHash::kMissing);
    bool inserted = false;
    EXPECT_EQ(hash.find_or_insert(0, 7, &inserted), 7u);
    EXPECT_TRUE(inserted);
}

}  // namespace
}  // namespace enteron::skinning
