// SPDX-License-Identifier: Apache-2.0
// The viewer's wall clock: steady (never jumps with the system's time), read by the
// panels' notices, the headless pacing and the remote link's ages.
#pragma once

#include <chrono>
#include <cstdint>

namespace viewer {

inline double wall_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

inline std::int64_t steady_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

}  // namespace viewer
