// SPDX-License-Identifier: Apache-2.0
// The state digest of scene_state_t and the journal: a 64-bit hash of the exact bits of a
// tick's outcome as the public API gives it: the control points after the step (x y z per
// point, ent_scene_control_points), the simulated time, and what each tool was given for
// that step (its pose and grasp action, as the journal records them). Velocities are not
// public; the positions at every tick are enough to tell a bit-identical replay from one
// that is not, since any difference in a velocity shows in the positions a tick later. The
// tools' part makes a changed journal entry show at its own tick, even when the bowel
// would not notice it (a tool in free space moved by one bit).
//
// Four independent lanes, each h <- (h xor w) * p (FNV-1a's step on 64-bit words), over the
// words in turn, then combined. Each lane step is a bijection in h and in w, so changing
// any one word always changes the digest; the four lanes let the multiplications overlap
// (a 240-point bowel hashes in well under a microsecond).
#pragma once

#include <cstddef>
#include <cstdint>

namespace enteron::lcm {

// What the digest takes of one tool: tip position (3), orientation w x y z (4), grasp
// action (journal_tool_t GRASP_*, as a double).
inline constexpr std::size_t kToolDigestValues = 8;

class StateDigest {
public:
    void add(const double* values, std::size_t count);
    int64_t value() const;

private:
    uint64_t lanes_[4] = {0xcbf29ce484222325ull, 0xcbf29ce484222326ull, 0xcbf29ce484222327ull,
                          0xcbf29ce484222328ull};  // FNV-1a's offset basis, + 0 to 3
    std::size_t count_ = 0;
};

// The digest of one tick: control points (3 per point), the simulated time, the tools' values.
int64_t tick_digest(const double* control_points, std::size_t control_point_values, double time_s,
                    const double* tool_values, std::size_t tool_value_count);

}  // namespace enteron::lcm
