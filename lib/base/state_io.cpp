// SPDX-License-Identifier: Apache-2.0
#include "base/state_io.h"

#include <cmath>
#include <cstdio>

#include "base/error.h"

namespace enteron {

namespace {

constexpr char kMagic[8] = {'E', 'N', 'T', 'S', 'T', 'A', 'T', 'E'};
constexpr uint32_t kByteOrderMark = 0x01020304u;

// Header fields, by offset (docs/scoring-and-state.md).
constexpr std::size_t kVersionAt = 8;
constexpr std::size_t kByteOrderAt = 12;
constexpr std::size_t kSizeAt = 16;
constexpr std::size_t kFingerprintAt = 24;
constexpr std::size_t kChecksumAt = 32;
constexpr std::size_t kSectionsAt = 40;

template <class T>
T load(const unsigned char* at) {
    T value;
    std::memcpy(&value, at, sizeof value);
    return value;
}

}  // namespace

uint64_t state_checksum(const unsigned char* data, std::size_t size) {
    uint64_t hash = 0xcbf29ce484222325ull;
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        hash ^= load<uint64_t>(data + i);
        hash *= 0x100000001b3ull;
        hash ^= hash >> 29;  // the high bits of a word reach the low bits of the next
    }
    for (; i < size; ++i) {
        hash ^= data[i];
        hash *= 0x100000001b3ull;
    }
    return hash;
}

// ---- writer ------------------------------------------------------------------------------

StateWriter::StateWriter(void* buffer, std::size_t capacity, uint64_t fingerprint)
    : buffer_(static_cast<unsigned char*>(buffer)),
      capacity_(buffer != nullptr ? capacity : 0),
      size_(kHeaderSize),
      fingerprint_(fingerprint) {}

void StateWriter::put_at(std::size_t offset, const void* data, std::size_t size) {
    if (offset + size <= capacity_) std::memcpy(buffer_ + offset, data, size);
}

void StateWriter::put(const void* data, std::size_t size) {
    put_at(size_, data, size);
    size_ += size;
}

void StateWriter::begin_section(const char* name, uint32_t version) {
    if (section_start_ != 0) throw Error(ErrorCode::internal, "state: a section began inside another");
    char padded[kNameSize] = {};
    const std::size_t length = std::strlen(name);
    if (length >= kNameSize) throw Error(ErrorCode::internal, "state: a section name longer than 15 characters");
    std::memcpy(padded, name, length);
    section_start_ = size_;
    put(padded, kNameSize);
    u32(version);
    u32(0);  // reserved
    u64(0);  // payload size, set by end_section
}

void StateWriter::end_section() {
    const uint64_t payload = size_ - section_start_ - kSectionHeaderSize;
    put_at(section_start_ + kNameSize + 8, &payload, sizeof payload);
    section_start_ = 0;
    sections_ += 1;
}

std::size_t StateWriter::finish() {
    if (size_ > capacity_) return size_;
    std::memcpy(buffer_, kMagic, sizeof kMagic);
    const uint32_t version = kFormatVersion, order = kByteOrderMark, reserved = 0;
    const uint64_t size = size_;
    const uint64_t checksum = state_checksum(buffer_ + kHeaderSize, size_ - kHeaderSize);
    put_at(kVersionAt, &version, sizeof version);
    put_at(kByteOrderAt, &order, sizeof order);
    put_at(kSizeAt, &size, sizeof size);
    put_at(kFingerprintAt, &fingerprint_, sizeof fingerprint_);
    put_at(kChecksumAt, &checksum, sizeof checksum);
    put_at(kSectionsAt, &sections_, sizeof sections_);
    put_at(kSectionsAt + 4, &reserved, sizeof reserved);
    return size_;
}

// ---- reader ------------------------------------------------------------------------------

StateReader::StateReader(const void* data, std::size_t size)
    : data_(static_cast<const unsigned char*>(data)), size_(size) {
    auto refuse = [](ErrorCode code, const std::string& message) { throw Error(code, "state: " + message); };
    if (data_ == nullptr || size < StateWriter::kHeaderSize)
        refuse(ErrorCode::invalid_argument, "size is " + std::to_string(size) + " bytes, less than the " +
                                                std::to_string(StateWriter::kHeaderSize) +
                                                "-byte header: not a saved state");
    if (std::memcmp(data_, kMagic, sizeof kMagic) != 0)
        refuse(ErrorCode::invalid_argument, "the data does not start with \"ENTSTATE\": not a saved state");
    const uint32_t version = load<uint32_t>(data_ + kVersionAt);
    if (version == 0 || version > StateWriter::kFormatVersion)
        refuse(ErrorCode::version, "format version " + std::to_string(version) + ", this library reads up to " +
                                       std::to_string(StateWriter::kFormatVersion));
    if (load<uint32_t>(data_ + kByteOrderAt) != kByteOrderMark)
        refuse(ErrorCode::invalid_argument, "written on a machine of another byte order");
    const uint64_t recorded = load<uint64_t>(data_ + kSizeAt);
    if (recorded != size)
        refuse(ErrorCode::invalid_argument, "size is " + std::to_string(size) + " bytes, the state says " +
                                                std::to_string(recorded) + " (truncated or padded?)");
    const uint64_t checksum = state_checksum(data_ + StateWriter::kHeaderSize, size - StateWriter::kHeaderSize);
    if (checksum != load<uint64_t>(data_ + kChecksumAt))
        refuse(ErrorCode::invalid_argument, "checksum mismatch: the data was changed after it was saved");
    fingerprint_ = load<uint64_t>(data_ + kFingerprintAt);
    sections_ = load<uint32_t>(data_ + kSectionsAt);
    rewind();
}

void StateReader::rewind() {
    at_ = StateWriter::kHeaderSize;
    section_end_ = 0;
    sections_read_ = 0;
    section_[0] = '\0';
}

void StateReader::start_applying() {
    checking_ = false;
    rewind();
}

void StateReader::fail(const std::string& message) const {
    const std::string where = section_[0] != '\0' ? "section '" + std::string(section_) + "': " : "";
    throw Error(ErrorCode::invalid_argument, "state: " + where + message);
}

const unsigned char* StateReader::take(std::size_t size, const char* what) {
    const std::size_t end = section_end_ != 0 ? section_end_ : size_;
    if (size > end - at_) fail(std::string(what) + " runs past the end of the section");
    const unsigned char* at = data_ + at_;
    at_ += size;
    return at;
}

uint32_t StateReader::begin_section(const char* name, uint32_t newest) {
    if (sections_read_ == sections_) fail(std::string("section '") + name + "' is missing (the state has " +
                                          std::to_string(sections_) + " sections)");
    if (StateWriter::kSectionHeaderSize > size_ - at_) fail(std::string("section '") + name + "' is cut short");
    const unsigned char* header = data_ + at_;
    char found[StateWriter::kNameSize + 1] = {};
    std::memcpy(found, header, StateWriter::kNameSize);
    if (std::strncmp(found, name, StateWriter::kNameSize) != 0 || std::strlen(name) >= StateWriter::kNameSize ||
        found[std::strlen(name)] != '\0')
        fail(std::string("expected section '") + name + "', found '" + std::string(found) +
             "' (saved from a scene with other effects?)");
    const uint32_t version = load<uint32_t>(header + StateWriter::kNameSize);
    const uint64_t payload = load<uint64_t>(header + StateWriter::kNameSize + 8);
    std::memcpy(section_, found, sizeof section_);
    if (version == 0 || version > newest)
        throw Error(version == 0 ? ErrorCode::invalid_argument : ErrorCode::version,
                    "state: section '" + std::string(name) + "' has version " + std::to_string(version) +
                        ", this library reads 1 to " + std::to_string(newest));
    at_ += StateWriter::kSectionHeaderSize;
    if (payload > size_ - at_) fail("its payload of " + std::to_string(payload) + " bytes runs past the end");
    section_end_ = at_ + static_cast<std::size_t>(payload);
    sections_read_ += 1;
    return version;
}

void StateReader::end_section() {
    if (at_ != section_end_)
        fail(std::to_string(section_end_ - at_) + " bytes left unread (a section of another layout)");
    section_end_ = 0;
    section_[0] = '\0';
}

void StateReader::finish() const {
    if (sections_read_ != sections_ || at_ != size_)
        throw Error(ErrorCode::invalid_argument, "state: " + std::to_string(sections_ - sections_read_) +
                                                     " sections more than this scene has (saved from a scene with "
                                                     "other effects?)");
}

uint8_t StateReader::u8(const char* what) { return *take(1, what); }
uint32_t StateReader::u32(const char* what) { return load<uint32_t>(take(4, what)); }
uint64_t StateReader::u64(const char* what) { return load<uint64_t>(take(8, what)); }
double StateReader::any_f64(const char* what) { return load<double>(take(8, what)); }

double StateReader::f64(const char* what) {
    const double value = any_f64(what);
    if (!std::isfinite(value)) {
        char number[32];
        std::snprintf(number, sizeof number, "%g", value);
        fail(std::string(what) + " is " + number + ", not a finite number");
    }
    return value;
}

uint32_t StateReader::count(const char* what, std::size_t most) {
    const uint32_t value = u32(what);
    if (value > most) fail(std::string(what) + " is " + std::to_string(value) + ", more than " + std::to_string(most));
    return value;
}

uint32_t StateReader::index(const char* what, std::size_t bound) {
    const uint32_t value = u32(what);
    if (value >= bound)
        fail(std::string(what) + " is " + std::to_string(value) + ", not below " + std::to_string(bound));
    return value;
}

bool StateReader::flag(const char* what) {
    const uint8_t value = u8(what);
    if (value > 1) fail(std::string(what) + " is " + std::to_string(value) + ", not 0 or 1");
    return value == 1;
}

void StateReader::f64s(const char* what, std::size_t count, double* out) {
    if (count > (size_ - at_) / sizeof(double)) fail(std::string(what) + " runs past the end of the section");
    for (std::size_t i = 0; i < count; ++i) {
        const double value = f64(what);
        if (out != nullptr) out[i] = value;
    }
}

void StateReader::any_f64s(const char* what, std::size_t count, double* out) {
    const unsigned char* at = take(count * sizeof(double), what);
    if (out != nullptr && count > 0) std::memcpy(out, at, count * sizeof(double));
}

void StateReader::u32s(const char* what, std::size_t count, uint32_t* out) {
    const unsigned char* at = take(count * sizeof(uint32_t), what);
    if (out != nullptr && count > 0) std::memcpy(out, at, count * sizeof(uint32_t));
}

}  // namespace enteron
