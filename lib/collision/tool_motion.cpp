// SPDX-License-Identifier: Apache-2.0
#include "collision/tool_motion.h"

#include <algorithm>

namespace enteron::collision {

namespace {

// Normalised linear interpolation of unit quaternions (w x y z) along the shorter arc.
Vec4 nlerp(const Vec4& a, const Vec4& b, double t) {
    const double sign = a.dot(b) < 0.0 ? -1.0 : 1.0;
    const Vec4 q = (1.0 - t) * a + (t * sign) * b;
    // Opposite quaternions are the same rotation, so the sum never vanishes after the sign flip.
    return q / q.norm();
}

}  // namespace

double StepSpan::fraction(double t) const {
    if (!(dt > 0.0)) return 0.0;
    return std::clamp((t - start) / dt, 0.0, 1.0);
}

double StepSpan::elapsed(double t) const { return dt > 0.0 ? std::max(0.0, t - start) : 0.0; }

Vec3 tail_of(const ToolPose& pose, double length) {
    return pose.position + length * quaternion_z_axis(pose.orientation);
}

ShaftAt commanded_shaft(const ToolPose& from, const ToolPose& to, double length, const StepSpan& step, double t,
                        double half_width) {
    const double alpha = step.fraction(t);
    ToolPose pose;
    pose.position = (1.0 - alpha) * from.position + alpha * to.position;
    const Eigen::Map<const Vec4> a(from.orientation.data()), b(to.orientation.data());
    Eigen::Map<Vec4>(pose.orientation.data()) = nlerp(a, b, alpha);
    ShaftAt shaft;
    shaft.tip = pose.position;
    shaft.tail = tail_of(pose, length);
    shaft.tip_velocity = shaft.tail_velocity = Vec3::Zero();
    if (step.dt > 0.0) {
        shaft.tip_velocity = (to.position - from.position) / step.dt;
        shaft.tail_velocity = (tail_of(to, length) - tail_of(from, length)) / step.dt;
    }
    if (half_width > 0.0) {
        shaft.side = half_width * quaternion_x_axis(pose.orientation);
        if (step.dt > 0.0)
            shaft.side_velocity =
                half_width * (quaternion_x_axis(to.orientation) - quaternion_x_axis(from.orientation)) / step.dt;
    }
    return shaft;
}

double blade_share(const ToolSettings& settings) {
    if (!(settings.blade_width > 0.0) || !(settings.length > 0.0)) return 0.0;
    return std::min(1.0, settings.blade_length / settings.length);
}

ShaftTravel commanded_travel(const ToolPose& from, const ToolPose& to, double length) {
    const Vec3 from_tail = tail_of(from, length), to_tail = tail_of(to, length);
    return {(to.position - from.position).norm(), (to_tail - from_tail).norm(),
            (to_tail - to.position - (from_tail - from.position)).norm()};
}

}  // namespace enteron::collision
