// SPDX-License-Identifier: Apache-2.0
#include "lcm/clock.h"

#include <time.h>

namespace enteron::lcm {

namespace {
int64_t read_ns(clockid_t clock) {
    timespec now{};
    clock_gettime(clock, &now);
    return static_cast<int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
}
}  // namespace

int64_t monotonic_ns() { return read_ns(CLOCK_MONOTONIC); }
int64_t realtime_us() { return read_ns(CLOCK_REALTIME) / 1000; }

UtimeFromMonotonic::UtimeFromMonotonic() : offset_ns_(read_ns(CLOCK_REALTIME) - read_ns(CLOCK_MONOTONIC)) {}

}  // namespace enteron::lcm
