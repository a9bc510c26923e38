// SPDX-License-Identifier: Apache-2.0
// An open-addressing hash map from 64-bit keys to 32-bit indices, cleared and refilled
// every frame by the marching cubes (voxel blocks, edge vertices). Unlike
// std::unordered_map it keeps its memory between frames and allocates only when it grows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace enteron::skinning {

class IndexHash {
public:
    static constexpr uint64_t kEmpty = ~uint64_t{0};
    static constexpr uint32_t kMissing = ~uint32_t{0};

    // Forgets every entry; keeps at least `expected` entries' room without growing.
    void clear(std::size_t expected) {
        std::size_t capacity = 64;
        while (capacity < 2 * expected) capacity *= 2;
        if (keys_.size() < capacity) {
            keys_.assign(capacity, kEmpty);
            values_.assign(capacity, 0);
        } else {
            std::fill(keys_.begin(), keys_.end(), kEmpty);
        }
        size_ = 0;
    }

    uint32_t find(uint64_t key) const {
        const std::size_t mask = keys_.size() - 1;
        for (std::size_t i = mix(key) & mask;; i = (i + 1) & mask) {
            if (keys_[i] == key) return values_[i];
            if (keys_[i] == kEmpty) return kMissing;
        }
    }

    // The value of key; if absent, inserts `value` and returns it, setting *inserted.
    uint32_t find_or_insert(uint64_t key, uint32_t value, bool* inserted) {
        if (2 * (size_ + 1) > keys_.size()) grow();
        const std::size_t mask = keys_.size() - 1;
        for (std::size_t i = mix(key) & mask;; i = (i + 1) & mask) {
            if (keys_[i] == key) {
                *inserted = false;
                return values_[i];
            }
            if (keys_[i] == kEmpty) {
                keys_[i] = key;
                values_[i] = value;
                ++size_;
                *inserted = true;
                return value;
            }
        }
    }

private:
    static std::size_t mix(uint64_t key) {
        key ^= key >> 33;
        key *= 0xff51afd7ed558ccdULL;
        key ^= key >> 33;
        return static_cast<std::size_t>(key);
    }
    void grow() {
        std::vector<uint64_t> keys;
        std::vector<uint32_t> values;
        keys.swap(keys_);
        values.swap(values_);
        keys_.assign(keys.empty() ? 64 : 2 * keys.size(), kEmpty);
        values_.assign(keys_.size(), 0);
        size_ = 0;
        bool inserted = false;
        for (std::size_t i = 0; i < keys.size(); ++i)
            if (keys[i] != kEmpty) find_or_insert(keys[i], values[i], &inserted);
    }

    std::vector<uint64_t> keys_;
    std::vector<uint32_t> values_;
    std::size_t size_ = 0;
};

}  // namespace enteron::skinning
