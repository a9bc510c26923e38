#include "collision/tool.h"

#include <cstdio>

namespace enteron::collision {

namespace {

// "tools[1].radius must be finite and > 0, got -1"; `what` names what is shown of the value.
[[noreturn]] void refuse(ErrorCode code, const std::string& name, const char* field, const char* rule,
                         double value, const char* what = "") {
    char number[64];
    std::snprintf(number, sizeof number, "%g", value);
    throw Error(code, name + "." + field + " must be " + rule + ", got " + what + number);
}

}  // namespace

ToolPose normalized_pose(const ToolPose& pose, const std::string& name, ErrorCode code) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(pose.position[c])) refuse(code, name, "position", "finite", pose.position[c]);
    double norm2 = 0.0;
    for (int c = 0; c < 4; ++c) {
        if (!std::isfinite(pose.orientation[c])) refuse(code, name, "orientation", "finite", pose.orientation[c]);
        norm2 += pose.orientation[c] * pose.orientation[c];
    }
    const double norm = std::sqrt(norm2);
    if (!(norm > 1e-12) || !std::isfinite(norm))
        refuse(code, name, "orientation", "a non-zero quaternion (w x y z)", norm, "norm ");
    ToolPose out = pose;
    for (double& c : out.orientation) c /= norm;
    return out;
}

void validate_tool_settings(const ToolSettings& s, const std::string& name, ErrorCode code) {
    if (!std::isfinite(s.radius) || !(s.radius > 0.0)) refuse(code, name, "radius", "finite and > 0", s.radius);
    if (!std::isfinite(s.length) || !(s.length >= 0.0)) refuse(code, name, "length", "finite and >= 0", s.length);
    if (!std::isfinite(s.max_force) || !(s.max_force > 0.0))
        refuse(code, name, "max_force", "finite and > 0", s.max_force);
    if (!std::isfinite(s.grasp_margin) || !(s.grasp_margin >= 0.0))
        refuse(code, name, "grasp_margin", "finite and >= 0", s.grasp_margin);
    if (!std::isfinite(s.grasp_stiffness) || !(s.grasp_stiffness > 0.0))
        refuse(code, name, "grasp_stiffness", "finite and > 0", s.grasp_stiffness);
    if (!std::isfinite(s.grasp_damping) || !(s.grasp_damping >= 0.0))
        refuse(code, name, "grasp_damping", "finite and >= 0", s.grasp_damping);
}

}  // namespace enteron::collision
