// SPDX-License-Identifier: Apache-2.0
// The saved-state image (lib/base/state_io.h): what StateWriter writes StateReader reads
// back, value for value, twice (checking, then applying); a writer without room only
// measures; and every damaged image is refused with its code and a message naming what is
// wrong: too short, another magic, a newer format, another byte order, truncated or
// padded, a changed byte, a missing, renamed, newer or unread section, a value past its
// section, a non-finite number, a count or an index out of range, a flag that is not 0/1,
// and sections left over.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/saved_image.h"
#include "base/state_io.h"
#include "refusal.h"
#include "saved_state_image.h"

namespace enteron {
namespace {

constexpr uint64_t kFingerprint = 0x0123456789abcdefull;

// An image of two sections: "alpha" v2 (a count, three doubles, a flag, an index) and
// "beta" v1 (uint32 values).
std::vector<unsigned char> image(double middle = 2.5, uint32_t count = 3, uint8_t flag = 1, uint32_t index = 4) {
    return state_test::saved_image([&](StateWriter& out) {
        out.begin_section("alpha", 2);
        out.u32(count);
        const double values[3] = {1.0, middle, -3.0};
        out.f64s(values, 3);
        out.u8(flag);
        out.u32(index);
        out.end_section();
        out.begin_section("beta", 1);
        const uint32_t words[2] = {7, 9};
        out.u32s(words, 2);
        out.u64(0xfeedull);
        out.end_section();
    }, kFingerprint);
}

// Reads image() back; throws what the reader throws.
void read(const std::vector<unsigned char>& bytes, uint32_t newest_alpha = 2) {
    StateReader in(bytes.data(), bytes.size());
    EXPECT_EQ(in.fingerprint(), kFingerprint);
    for (int pass = 0; pass < 2; ++pass) {
        EXPECT_EQ(in.checking(), pass == 0);
        EXPECT_EQ(in.begin_section("alpha", newest_alpha), 2u);
        const uint32_t count = in.count("the count", 3);
        double values[3];
        in.f64s("the values", count, values);
        EXPECT_EQ(values[1], 2.5);
        EXPECT_TRUE(in.flag("the flag"));
        EXPECT_EQ(in.index("the index", 5), 4u);
        in.end_section();
        EXPECT_EQ(in.begin_section("beta", 1), 1u);
        uint32_t words[2];
        in.u32s("the words", 2, words);
        EXPECT_EQ(words[1], 9u);
        EXPECT_EQ(in.u64("the tail"), 0xfeedull);
        in.end_section();
        in.finish();
        if (pass == 0) in.start_applying();
    }
}

using unit_test::refusal;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Writes `value` at `offset` and seals the checksum again, so that the damage reaches the
// reader's later checks.
template <class T>
std::vector<unsigned char> patched(std::vector<unsigned char> bytes, std::size_t offset, T value, bool reseal = true) {
    std::memcpy(bytes.data() + offset, &value, sizeof value);
    if (reseal) saved_state_image::seal_checksum(bytes.data(), bytes.size());  // from docs/scoring-and-state.md
    return bytes;
}

// Offsets in image(): the header, alpha's section header, its payload.
constexpr std::size_t kAlpha = StateWriter::kHeaderSize, kAlphaPayload = kAlpha + StateWriter::kSectionHeaderSize;
constexpr std::size_t kBeta = kAlphaPayload + 4 + 24 + 1 + 4;

TEST(StateIo, WhatTheWriterWritesTheReaderReadsTwice) {
    const std::vector<unsigned char> bytes = image();
    EXPECT_EQ(bytes.size(), kBeta + StateWriter::kSectionHeaderSize + 8 + 8);
    EXPECT_EQ(std::memcmp(bytes.data(), "ENTSTATE", 8), 0);
    read(bytes);
}

TEST(StateIo, AWriterWithoutRoomOnlyMeasures) {
    const std::vector<unsigned char> whole = image();
    std::vector<unsigned char> small(whole.size() - 1, 0xaa);
    StateWriter out(small.data(), small.size(), kFingerprint);
    out.begin_section("alpha", 1);
    for (std::size_t i = 0; i < whole.size(); ++i) out.u8(1);
    out.end_section();
    EXPECT_GT(out.finish(), small.size()) << "it says it did not fit";
    EXPECT_EQ(small[0], 0xaa) << "and wrote no header";
    EXPECT_EQ(refusal([] {
                  StateWriter w(nullptr, 0, 0);
                  w.begin_section("a name of sixteen", 1);
              }, ErrorCode::internal),
              "state: a section name longer than 15 characters");
}

TEST(StateIo, DamagedHeadersAreRefusedNamingTheDamage) {
    const std::vector<unsigned char> good = image();
    std::vector<unsigned char> bytes(good.begin(), good.begin() + 40);
    EXPECT_EQ(refusal([&] { read(bytes); }), "state: size is 40 bytes, less than the 48-byte header: not a saved state");
    bytes = good;
    bytes[0] = 'X';
    EXPECT_TRUE(has(refusal([&] { read(bytes); }), "does not start with \"ENTSTATE\""));
    EXPECT_EQ(refusal([&] { read(patched<uint32_t>(good, 8, 2, false)); }, ErrorCode::version),
              "state: format version 2, this library reads up to 1");
    EXPECT_TRUE(has(refusal([&] { read(patched<uint32_t>(good, 8, 0, false)); }, ErrorCode::version), "format version 0"));
    EXPECT_EQ(refusal([&] { read(patched<uint32_t>(good, 12, 0x04030201u, false)); }),
              "state: written on a machine of another byte order");
    bytes.assign(good.begin(), good.end() - 1);
    EXPECT_TRUE(has(refusal([&] { read(bytes); }), "(truncated or padded?)"));
    bytes = good;
    bytes.push_back(0);
    EXPECT_TRUE(has(refusal([&] { read(bytes); }), "the state says " + std::to_string(good.size())));
    bytes = good;
    bytes[kAlphaPayload + 8] ^= 1;
    EXPECT_EQ(refusal([&] { read(bytes); }), "state: checksum mismatch: the data was changed after it was saved");
}

TEST(StateIo, DamagedSectionsAreRefusedNamingTheSectionAndTheValue) {
    const std::vector<unsigned char> good = image();
    // Values (the checksum sealed again, as a forger would).
    EXPECT_EQ(refusal([&] { read(image(std::nan(""))); }), "state: section 'alpha': the values is nan, not a finite number");
    EXPECT_EQ(refusal([&] { read(image(2.5, 4)); }), "state: section 'alpha': the count is 4, more than 3");
    EXPECT_EQ(refusal([&] { read(image(2.5, 3, 2)); }), "state: section 'alpha': the flag is 2, not 0 or 1");
    EXPECT_EQ(refusal([&] { read(image(2.5, 3, 1, 5)); }), "state: section 'alpha': the index is 5, not below 5");
    // Sections.
    EXPECT_EQ(refusal([&] { read(good, 1); }, ErrorCode::version),
              "state: section 'alpha' has version 2, this library reads 1 to 1");
    EXPECT_TRUE(has(refusal([&] { read(patched<char>(good, kAlpha, 'A')); }),
                    "expected section 'alpha', found 'Alpha' (saved from a scene with other effects?)"));
    EXPECT_TRUE(has(refusal([&] { read(patched<uint32_t>(good, 40, 1)); }), "section 'beta' is missing (the state has 1 sections)"));
    EXPECT_TRUE(has(refusal([&] { read(patched<uint32_t>(good, 40, 3)); }), "1 sections more than this scene has"));
    // alpha's payload one byte longer: its last value is then not all read.
    EXPECT_TRUE(has(refusal([&] { read(patched<uint64_t>(good, kAlpha + 24, 4 + 24 + 1 + 4 + 1)); }), "1 bytes left unread"));
    EXPECT_TRUE(has(refusal([&] { read(patched<uint64_t>(good, kAlpha + 24, 4 + 24)); }), "the flag runs past the end of the section"));
    EXPECT_TRUE(has(refusal([&] { read(patched<uint64_t>(good, kAlpha + 24, 1u << 20)); }), "runs past the end"));
}

TEST(StateIo, TheChecksumSeesEveryByteAndItsPlace) {
    std::vector<unsigned char> data(37);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<unsigned char>(i * 7);
    const uint64_t base = state_checksum(data.data(), data.size());
    for (std::size_t i = 0; i < data.size(); ++i) {
        std::vector<unsigned char> changed = data;
        changed[i] ^= 0x10;
        EXPECT_NE(state_checksum(changed.data(), changed.size()), base) << "byte " << i;
    }
    std::vector<unsigned char> swapped = data;
    std::swap(swapped[0], swapped[8]);  // two words' first bytes
    EXPECT_NE(state_checksum(swapped.data(), swapped.size()), base);
    Fingerprint a, b;
    a.add(uint64_t{1});
    a.add(2.0);
    b.add(2.0);
    b.add(uint64_t{1});
    EXPECT_NE(a.value(), b.value()) << "the order counts";
}

}  // namespace
}  // namespace enteron
