// SPDX-License-Identifier: Apache-2.0
// A saved state's header and checksum as the tests see them (docs/scoring-and-state.md,
// "The image"), so that a test or a fuzzer can change a value in a saved state and re-seal
// it: the checksum then matches and the damage reaches the check of that value. Written out
// here from the documented format rather than taken from the library (lib/base/state_io.cpp),
// so that the tests check the library against the documentation. Shared by
// tests/capi/test_save_restore.cpp and tests/fuzz/fuzz_restore_state.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace saved_state_image {

// Header fields, by offset; the body (the sections) starts at kHeaderSize.
constexpr std::size_t kVersionAt = 8;
constexpr std::size_t kSizeAt = 16;
constexpr std::size_t kChecksumAt = 32;
constexpr std::size_t kHeaderSize = 48;
// Each section starts with a 32-byte header (name, version, reserved, payload size).
constexpr std::size_t kSectionHeaderSize = 32;
// The first section (`scene`) holds the control point count (4 bytes), the time (a
// double), then the control points' positions (doubles).
constexpr std::size_t kTimeAt = kHeaderSize + kSectionHeaderSize + 4;
constexpr std::size_t kPositionsAt = kTimeAt + 8;

// 64-bit FNV-1a over the body's 64-bit words, with a shift that carries a word's high bits
// to the next word's low bits; the last bytes one by one.
inline uint64_t body_checksum(const unsigned char* body, std::size_t size) {
    uint64_t hash = 0xcbf29ce484222325ull;
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        uint64_t word;
        std::memcpy(&word, body + i, sizeof word);
        hash ^= word;
        hash *= 0x100000001b3ull;
        hash ^= hash >> 29;
    }
    for (; i < size; ++i) {
        hash ^= body[i];
        hash *= 0x100000001b3ull;
    }
    return hash;
}

// Writes the checksum of the body into the header (an image of at least kHeaderSize bytes).
inline void seal_checksum(unsigned char* image, std::size_t size) {
    const uint64_t sum = body_checksum(image + kHeaderSize, size - kHeaderSize);
    std::memcpy(image + kChecksumAt, &sum, sizeof sum);
}

// Writes the image's size and checksum into its header, as the library does when it saves.
inline void reseal(std::vector<unsigned char>& image) {
    const uint64_t size = image.size();
    std::memcpy(image.data() + kSizeAt, &size, sizeof size);
    seal_checksum(image.data(), image.size());
}

}  // namespace saved_state_image
