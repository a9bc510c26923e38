// SPDX-License-Identifier: Apache-2.0
#include "tool_exchange.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace viewer {

ToolPose follow(const ToolPose& from, const ToolPose& to, double dt_s, double max_speed_m_per_s,
                double max_turn_rad_per_s) {
    ToolPose next;
    // The tip: a straight move of at most v dt.
    const Eigen::Map<const Eigen::Vector3d> p0(from.position_m), p1(to.position_m);
    const Eigen::Vector3d move = p1 - p0;
    const double distance = move.norm();
    const double reach = max_speed_m_per_s * dt_s;
    Eigen::Map<Eigen::Vector3d>(next.position_m) = distance <= reach ? p1 : Eigen::Vector3d(p0 + move * (reach / distance));
    // The orientation: slerp through at most omega dt.
    const Eigen::Quaterniond q0(from.orientation_wxyz[0], from.orientation_wxyz[1], from.orientation_wxyz[2],
                                from.orientation_wxyz[3]);
    const Eigen::Quaterniond q1(to.orientation_wxyz[0], to.orientation_wxyz[1], to.orientation_wxyz[2],
                                to.orientation_wxyz[3]);
    const double angle = q0.normalized().angularDistance(q1.normalized());
    const double turn = max_turn_rad_per_s * dt_s;
    const Eigen::Quaterniond q = angle <= turn ? q1.normalized() : q0.normalized().slerp(turn / angle, q1.normalized());
    next.orientation_wxyz[0] = q.w();
    next.orientation_wxyz[1] = q.x();
    next.orientation_wxyz[2] = q.y();
    next.orientation_wxyz[3] = q.z();
    return next;
}

}  // namespace viewer
