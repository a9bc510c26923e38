// SPDX-License-Identifier: Apache-2.0
// The saved state of a scene (ent_scene_save_state, ent_scene_restore_state): a versioned,
// self-describing binary image, laid out in docs/scoring-and-state.md.
//
//   header    magic "ENTSTATE", format version, byte order mark, total size, the scene's
//             fingerprint, a checksum of everything after the header, the section count
//   sections  each: a name (16 bytes, NUL-padded), its version, its payload size, then the
//             payload: little-endian integers and IEEE 754 doubles, packed, no padding
//
// Every stateful component writes and reads its own section through these two classes
// (Effect::save_state and restore_state, Integrator's, the scene's own), so a component
// that gains state only changes its section. Restore reads the image twice: first to check
// (checking(): every section is read and validated and nothing changes), then, if all was
// well, to apply. A component reads its values into locals, validates them, and assigns
// them only when !checking(): a bad image leaves the scene untouched.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace enteron {

// FNV-1a, 64 bits: the scene's fingerprint (what the state belongs to) and the image's
// checksum are made with it.
class Fingerprint {
public:
    void add_bytes(const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            value_ ^= bytes[i];
            value_ *= 0x100000001b3ull;
        }
    }
    void add(uint64_t value) { add_bytes(&value, sizeof value); }
    void add(double value) { add_bytes(&value, sizeof value); }
    uint64_t value() const { return value_; }

private:
    uint64_t value_ = 0xcbf29ce484222325ull;
};

// The checksum of an image's body: FNV-1a over its 64-bit words (and the tail bytes), fast
// enough for a state of a few hundred kilobytes.
uint64_t state_checksum(const unsigned char* data, std::size_t size);

class StateWriter {
public:
    // The current format version; a reader refuses a newer one with ErrorCode::version.
    static constexpr uint32_t kFormatVersion = 1;
    static constexpr std::size_t kHeaderSize = 48;
    static constexpr std::size_t kSectionHeaderSize = 32;
    static constexpr std::size_t kNameSize = 16;

    // Writes into `buffer` (`capacity` bytes); with a null buffer it only measures. Bytes
    // past the capacity are counted, not written: finish() then says it did not fit.
    StateWriter(void* buffer, std::size_t capacity, uint64_t fingerprint);

    // A section `name` (at most 15 characters) of version `version`; end it before the next.
    void begin_section(const char* name, uint32_t version);
    void end_section();

    void u8(uint8_t value) { put(&value, 1); }
    void u32(uint32_t value) { put(&value, sizeof value); }
    void u64(uint64_t value) { put(&value, sizeof value); }
    void f64(double value) { put(&value, sizeof value); }
    void f64s(const double* values, std::size_t count) { put(values, count * sizeof(double)); }
    void u32s(const uint32_t* values, std::size_t count) { put(values, count * sizeof(uint32_t)); }

    // Writes the header (size, section count, checksum). Returns the image's size in bytes;
    // it fitted if that is at most the capacity.
    std::size_t finish();

private:
    void put(const void* data, std::size_t size);
    void put_at(std::size_t offset, const void* data, std::size_t size);

    unsigned char* buffer_;
    std::size_t capacity_;
    std::size_t size_;
    uint64_t fingerprint_;
    uint32_t sections_ = 0;
    std::size_t section_start_ = 0;  // of the open section's header; 0: none open
};

class StateReader {
public:
    // Checks the header: magic, format version (newer: ErrorCode::version), byte order,
    // size (must be `size`), checksum. Throws Error(invalid_argument or version) naming
    // what is wrong. The data must outlive the reader.
    StateReader(const void* data, std::size_t size);

    uint64_t fingerprint() const { return fingerprint_; }

    // True in the first pass (validate only), false in the second (apply).
    bool checking() const { return checking_; }
    // Starts the second pass: the sections are read again from the first.
    void start_applying();

    // Opens the next section, which must be `name` with a version from 1 to `newest`
    // (a newer one: ErrorCode::version). Returns its version.
    uint32_t begin_section(const char* name, uint32_t newest);
    // Closes it: every byte of its payload must have been read.
    void end_section();
    // After the last section: nothing may be left.
    void finish() const;

    uint8_t u8(const char* what);
    uint32_t u32(const char* what);
    uint64_t u64(const char* what);
    // A finite double (what names it in the error).
    double f64(const char* what);
    // Any double, NaN and infinities included (caches that may hold them).
    double any_f64(const char* what);
    // A count that must not exceed `most`.
    uint32_t count(const char* what, std::size_t most);
    // An index that must be below `bound`.
    uint32_t index(const char* what, std::size_t bound);
    // A flag: 0 or 1.
    bool flag(const char* what);

    // `count` finite doubles / any doubles / uint32 values, copied into `out` unless it is
    // null (pass null while checking, or a scratch array to validate them).
    void f64s(const char* what, std::size_t count, double* out);
    void any_f64s(const char* what, std::size_t count, double* out);
    void u32s(const char* what, std::size_t count, uint32_t* out);

    // The next `size` bytes as they are in the image (valid while the data lives): for
    // values a component reads more than once, without copying them.
    const unsigned char* raw(const char* what, std::size_t size) { return take(size, what); }

    // Throws Error(invalid_argument) with "state: section '<name>': <message>".
    [[noreturn]] void fail(const std::string& message) const;

private:
    const unsigned char* take(std::size_t size, const char* what);
    void rewind();

    const unsigned char* data_;
    std::size_t size_;
    uint64_t fingerprint_ = 0;
    uint32_t sections_ = 0;
    uint32_t sections_read_ = 0;
    std::size_t at_ = 0;
    std::size_t section_end_ = 0;  // 0: no section open
    char section_[StateWriter::kNameSize + 1] = "";
    bool checking_ = true;
};

}  // namespace enteron
