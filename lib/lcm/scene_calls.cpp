// SPDX-License-Identifier: Apache-2.0
#include "lcm/scene_calls.h"

#include <algorithm>

#include "lcm/state_digest.h"

namespace enteron::lcm {

ent_status give_tool(ent_scene* scene, int32_t tool, const double position_m[3], const double orientation_wxyz[4],
                     GraspAction action, double* digest_values) {
    std::copy(position_m, position_m + 3, digest_values);
    std::copy(orientation_wxyz, orientation_wxyz + 4, digest_values + 3);
    digest_values[7] = static_cast<double>(action);
    ent_status status = ent_tool_set_pose(scene, tool, position_m, orientation_wxyz);
    if (status != ENT_OK) return status;
    if (action == GraspAction::grasp) status = ent_tool_grasp(scene, tool);
    if (action == GraspAction::release) status = ent_tool_release(scene, tool);
    return status;
}

ent_status step_and_digest(ent_scene* scene, double dt_s, const std::vector<double>& tool_digest_values,
                           std::vector<double>& control_points, ent_stats& stats, int64_t& digest) {
    const ent_status status = ent_scene_step(scene, dt_s);
    uint32_t count = 0;
    stats.struct_size = sizeof stats;
    if (ent_scene_control_points(scene, static_cast<uint32_t>(control_points.size() / 3), control_points.data(),
                                 &count) != ENT_OK ||
        ent_scene_stats(scene, &stats) != ENT_OK)
        return ENT_ERROR_INTERNAL;
    digest = tick_digest(control_points.data(), 3 * static_cast<std::size_t>(count), stats.time_s,
                         tool_digest_values.data(), tool_digest_values.size());
    return status;
}

}  // namespace enteron::lcm
