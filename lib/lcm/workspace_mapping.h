// SPDX-License-Identifier: Apache-2.0
// The workspace mapping: from a haptic device's frame and units into the scene's, and the
// forces back (enteron_lcm.h, ent_lcm_bridge_desc). With s the scale, R the rotation of the
// device's axes into the scene's, o the offset and g the force scale:
//   p_scene = o + s R p_device          q_scene = q_R q_device
//   F_device = g R^T F_scene            T_device = (g / s) R^T T_scene
//   K_device = g s R^T K_scene R
// The torque and the stiffness follow from the force: T = r x F with r in device units,
// K = dF/dx with x in device units.
#pragma once

#include <Eigen/Geometry>

namespace enteron::lcm {

struct Pose {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // unit
};

class WorkspaceMapping {
public:
    WorkspaceMapping() = default;
    // rotation need not be unit; it must not be zero (checked by the caller).
    WorkspaceMapping(double scale, const Eigen::Quaterniond& rotation, const Eigen::Vector3d& offset,
                     double force_scale);

    // A device pose into the scene; the orientation need not be unit (not zero).
    Pose to_scene(const Eigen::Vector3d& device_position, const Eigen::Quaterniond& device_orientation) const;
    // A scene pose into the device's frame.
    Pose to_device(const Pose& scene) const;

    Eigen::Vector3d force_to_device(const Eigen::Vector3d& scene_force) const;
    Eigen::Vector3d force_to_scene(const Eigen::Vector3d& device_force) const;
    Eigen::Vector3d torque_to_device(const Eigen::Vector3d& scene_torque) const;
    Eigen::Matrix3d stiffness_to_device(const Eigen::Matrix3d& scene_stiffness) const;

    double force_scale() const { return force_scale_; }

private:
    double scale_ = 1.0;
    Eigen::Quaterniond rotation_ = Eigen::Quaterniond::Identity();
    Eigen::Matrix3d rotation_matrix_ = Eigen::Matrix3d::Identity();
    Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();
    double force_scale_ = 1.0;
};

}  // namespace enteron::lcm
