// SPDX-License-Identifier: Apache-2.0
#include "lcm/state_digest.h"

#include <cstring>

namespace enteron::lcm {

namespace {
constexpr uint64_t kPrime = 0x100000001b3ull;  // FNV-1a's 64-bit prime

uint64_t bits_of(double value) {
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}
}  // namespace

void StateDigest::add(const double* values, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i, ++count_) {
        uint64_t& lane = lanes_[count_ % 4];
        lane = (lane ^ bits_of(values[i])) * kPrime;
    }
}

int64_t StateDigest::value() const {
    uint64_t digest = 0xcbf29ce484222325ull ^ count_;
    for (uint64_t lane : lanes_) digest = (digest ^ lane) * kPrime;
    return static_cast<int64_t>(digest);
}

int64_t tick_digest(const double* control_points, std::size_t control_point_values, double time_s,
                    const double* tool_values, std::size_t tool_value_count) {
    StateDigest digest;
    digest.add(control_points, control_point_values);
    digest.add(&time_s, 1);
    digest.add(tool_values, tool_value_count);
    return digest.value();
}

}  // namespace enteron::lcm
