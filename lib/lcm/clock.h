// SPDX-License-Identifier: Apache-2.0
// The bridge's clocks: CLOCK_MONOTONIC for everything it judges (deadlines, the watchdog,
// command ages), CLOCK_REALTIME only for the `utime` stamps of messages (microseconds since
// the epoch, what lcm-logger writes too).
#pragma once

#include <cstdint>

namespace enteron::lcm {

int64_t monotonic_ns();
int64_t realtime_us();

// Turns monotonic times into utime without reading the clock again (the tick reads none):
// the offset between the two clocks, taken once.
class UtimeFromMonotonic {
public:
    UtimeFromMonotonic();
    int64_t operator()(int64_t monotonic_ns) const { return (monotonic_ns + offset_ns_) / 1000; }

private:
    int64_t offset_ns_;
};

}  // namespace enteron::lcm
