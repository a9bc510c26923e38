// SPDX-License-Identifier: Apache-2.0
// The input of a libFuzzer target read as values, front to back: bytes, 32-bit integers,
// and numbers near a typical value (most of the time) or edge values and raw bits (the
// rest). Past the end every read gives zero, so any input is a complete program.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

namespace fuzz {

// Reads the input front to back; past its end every read gives zero.
class Bytes {
public:
    Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    bool empty() const { return at_ >= size_; }
    uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
    uint32_t u32() {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= uint32_t{u8()} << (8 * i);
        return v;
    }
    // A number near `typical` most of the time, an edge value or raw bits otherwise.
    double number(double typical) {
        const uint8_t kind = u8();
        if (kind < 128) return typical * (0.25 + kind / 64.0);  // 0.25 .. 2.2 x typical
        if (kind < 240) {
            static const double edges[] = {0.0, -0.0, -1.0, 1.0, 1e-3, 0.05, 1e-300, 5e-324, DBL_MAX, -DBL_MAX,
                                           1e300, std::numeric_limits<double>::quiet_NaN(),
                                           std::numeric_limits<double>::infinity(),
                                           -std::numeric_limits<double>::infinity(), DBL_MIN, 1e9};
            return edges[kind % (sizeof edges / sizeof edges[0])];
        }
        uint64_t bits = uint64_t{u32()} | (uint64_t{u32()} << 32);
        double v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }

private:
    const uint8_t* data_;
    size_t size_;
    size_t at_ = 0;
};

}  // namespace fuzz
