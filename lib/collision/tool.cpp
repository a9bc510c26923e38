#include "collision/tool.h"

#include <cstdio>

namespace enteron::collision {

namespace {

constexpr double kMaxToolRadius = 1.0;   // m, also the largest grasp margin
constexpr double kMaxToolLength = 10.0;  // m

// "tools[1].radius must be finite and > 0, got -1"; `what` names what is shown of the value.
[[noreturn]] void refuse(ErrorCode code, const std::string& prefix, const char* field, const char* rule,
                         double value, const char* what = "") {
    char number[64];
    std::snprintf(number, sizeof number, "%g", value);
    throw Error(code, prefix + field + " must be " + rule + ", got " + what + number);
}

}  // namespace

ToolPose normalized_pose(const ToolPose& pose, const std::string& prefix, const ToolFieldNames& names,
                         ErrorCode code) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(pose.position[c])) refuse(code, prefix, names.position, "finite", pose.position[c]);
    double norm2 = 0.0;
    for (int c = 0; c < 4; ++c) {
        if (!std::isfinite(pose.orientation[c])) refuse(code, prefix, names.orientation, "finite", pose.orientation[c]);
        norm2 += pose.orientation[c] * pose.orientation[c];
    }
    const double norm = std::sqrt(norm2);
    if (!(norm > 1e-12) || !std::isfinite(norm))
        refuse(code, prefix, names.orientation, "a non-zero quaternion (w x y z)", norm, "norm ");
    ToolPose out = pose;
    for (double& c : out.orientation) c /= norm;
    return out;
}

void validate_tool_settings(const ToolSettings& s, const std::string& prefix, const ToolFieldNames& names,
                            ErrorCode code) {
    // Upper bounds on the sizes keep every contact's depth, and so its energy, finite: a
    // tool 1e200 m wide is finite but gave the bowel an infinite potential energy.
    if (!(s.radius > 0.0 && s.radius <= kMaxToolRadius))
        refuse(code, prefix, names.radius, "> 0 and <= 1 (m)", s.radius);
    if (!(s.length >= 0.0 && s.length <= kMaxToolLength))
        refuse(code, prefix, names.length, ">= 0 and <= 10 (m)", s.length);
    if (!std::isfinite(s.max_force) || !(s.max_force > 0.0))
        refuse(code, prefix, names.max_force, "finite and > 0", s.max_force);
    if (!(s.grasp_margin >= 0.0 && s.grasp_margin <= kMaxToolRadius))
        refuse(code, prefix, names.grasp_margin, ">= 0 and <= 1 (m)", s.grasp_margin);
    if (!std::isfinite(s.grasp_stiffness) || !(s.grasp_stiffness > 0.0))
        refuse(code, prefix, names.grasp_stiffness, "finite and > 0", s.grasp_stiffness);
    if (!std::isfinite(s.grasp_damping) || !(s.grasp_damping >= 0.0))
        refuse(code, prefix, names.grasp_damping, "finite and >= 0", s.grasp_damping);
}

}  // namespace enteron::collision
