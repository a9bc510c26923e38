// SPDX-License-Identifier: Apache-2.0
// The calls a tick makes on the scene, in the order the journal records them and the
// replay repeats them: for each tool ent_tool_set_pose, then its grasp action; then
// ent_scene_step, and the state digest of what it reached (state_digest.h).
#pragma once

#include <cstdint>
#include <vector>

#include "enteron/enteron.h"
#include "lcm/tool_safety.h"

namespace enteron::lcm {

// Gives the tool its pose and grasp action, and writes what it was given into
// digest_values (kToolDigestValues doubles) for the tick's digest.
ent_status give_tool(ent_scene* scene, int32_t tool, const double position_m[3], const double orientation_wxyz[4],
                     GraspAction action, double* digest_values);

// Steps by dt_s, then reads the control points (into `control_points`, sized 3 n) and the
// stats of the state reached, and hashes them with the tools' digest values. Returns the
// step's status (the digest is of the state as it then is: unchanged after a failed step).
ent_status step_and_digest(ent_scene* scene, double dt_s, const std::vector<double>& tool_digest_values,
                           std::vector<double>& control_points, ent_stats& stats, int64_t& digest);

}  // namespace enteron::lcm
