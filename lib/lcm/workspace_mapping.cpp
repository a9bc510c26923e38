// SPDX-License-Identifier: Apache-2.0
#include "lcm/workspace_mapping.h"

namespace enteron::lcm {

WorkspaceMapping::WorkspaceMapping(double scale, const Eigen::Quaterniond& rotation, const Eigen::Vector3d& offset,
                                   double force_scale)
    : scale_(scale),
      rotation_(rotation.normalized()),
      rotation_matrix_(rotation_.toRotationMatrix()),
      offset_(offset),
      force_scale_(force_scale) {}

Pose WorkspaceMapping::to_scene(const Eigen::Vector3d& device_position,
                                const Eigen::Quaterniond& device_orientation) const {
    Pose scene;
    scene.position = offset_ + scale_ * (rotation_matrix_ * device_position);
    scene.orientation = (rotation_ * device_orientation.normalized()).normalized();
    return scene;
}

Pose WorkspaceMapping::to_device(const Pose& scene) const {
    Pose device;
    device.position = rotation_matrix_.transpose() * (scene.position - offset_) / scale_;
    device.orientation = (rotation_.conjugate() * scene.orientation).normalized();
    return device;
}

Eigen::Vector3d WorkspaceMapping::force_to_device(const Eigen::Vector3d& scene_force) const {
    return force_scale_ * (rotation_matrix_.transpose() * scene_force);
}

Eigen::Vector3d WorkspaceMapping::force_to_scene(const Eigen::Vector3d& device_force) const {
    return (rotation_matrix_ * device_force) / force_scale_;
}

Eigen::Vector3d WorkspaceMapping::torque_to_device(const Eigen::Vector3d& scene_torque) const {
    return (force_scale_ / scale_) * (rotation_matrix_.transpose() * scene_torque);
}

Eigen::Matrix3d WorkspaceMapping::stiffness_to_device(const Eigen::Matrix3d& scene_stiffness) const {
    return (force_scale_ * scale_) * (rotation_matrix_.transpose() * scene_stiffness * rotation_matrix_);
}

}  // namespace enteron::lcm
