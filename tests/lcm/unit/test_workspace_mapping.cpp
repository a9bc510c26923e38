// SPDX-License-Identifier: Apache-2.0
// The workspace mapping (workspace_mapping.h) against hand-computed frames, and its
// force, torque and stiffness maps against the definitions they follow from.
#include <gtest/gtest.h>

#include <cmath>

#include "lcm/workspace_mapping.h"

namespace enteron::lcm {
namespace {

// A device reporting millimetres, its x axis along the scene's y (a quarter turn about z),
// its origin at (0.1, 0, 0.05) m in the scene, rendering forces at half scale.
WorkspaceMapping millimetre_device() {
    const Eigen::Quaterniond quarter_turn_z(std::cos(M_PI / 4), 0, 0, std::sin(M_PI / 4));
    return WorkspaceMapping(0.001, quarter_turn_z, Eigen::Vector3d(0.1, 0.0, 0.05), 0.5);
}

TEST(WorkspaceMapping, MapsDevicePosesIntoTheSceneAndBack) {
    const WorkspaceMapping mapping = millimetre_device();
    const Pose scene = mapping.to_scene(Eigen::Vector3d(10, 0, 20), Eigen::Quaterniond(2, 0, 0, 0));
    // 10 mm along the device's x is 1 cm along the scene's y.
    EXPECT_NEAR(scene.position.x(), 0.1, 1e-15);
    EXPECT_NEAR(scene.position.y(), 0.01, 1e-15);
    EXPECT_NEAR(scene.position.z(), 0.07, 1e-15);
    // The identity of the device (given unnormalised) is the quarter turn in the scene.
    EXPECT_NEAR(scene.orientation.w(), std::cos(M_PI / 4), 1e-15);
    EXPECT_NEAR(scene.orientation.z(), std::sin(M_PI / 4), 1e-15);
    const Pose back = mapping.to_device(scene);
    EXPECT_NEAR((back.position - Eigen::Vector3d(10, 0, 20)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(back.orientation.angularDistance(Eigen::Quaterniond::Identity()), 0.0, 1e-12);
}

TEST(WorkspaceMapping, ForcesGoBackThroughTheTransposedRotationAndTheForceScale) {
    const WorkspaceMapping mapping = millimetre_device();
    // 2 N along the scene's y is along the device's x, at half scale.
    const Eigen::Vector3d device = mapping.force_to_device(Eigen::Vector3d(0, 2, 0));
    EXPECT_NEAR((device - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((mapping.force_to_scene(device) - Eigen::Vector3d(0, 2, 0)).norm(), 0.0, 1e-15);
}

// With a linear law F_scene = K_scene p_scene, the device's force changes by K_device dx
// when the device moves by dx (its own units): the stiffness map is that derivative.
TEST(WorkspaceMapping, StiffnessIsTheDerivativeOfTheDeviceForceInDeviceUnits) {
    const WorkspaceMapping mapping = millimetre_device();
    Eigen::Matrix3d k_scene;
    k_scene << 300, 20, 0, 20, 150, -10, 0, -10, 80;  // N/m
    const auto device_force = [&](const Eigen::Vector3d& device_position) {
        const Pose scene = mapping.to_scene(device_position, Eigen::Quaterniond::Identity());
        return mapping.force_to_device(k_scene * scene.position);
    };
    const Eigen::Vector3d x(3, -4, 12), dx(0.5, 0.25, -1.0);  // mm
    const Eigen::Vector3d expected = device_force(x + dx) - device_force(x);
    EXPECT_NEAR((mapping.stiffness_to_device(k_scene) * dx - expected).norm(), 0.0, 1e-12);
}

// The torque of a force about the tip, both mapped: r x F in device units.
TEST(WorkspaceMapping, TorqueIsTheMomentOfTheMappedForce) {
    const WorkspaceMapping mapping = millimetre_device();
    const Eigen::Vector3d lever_scene(0.02, -0.01, 0.03), force_scene(1.0, 2.0, -0.5);
    const Eigen::Vector3d lever_device =
        mapping.to_device(Pose{lever_scene + Eigen::Vector3d(0.1, 0, 0.05), Eigen::Quaterniond::Identity()}).position;
    const Eigen::Vector3d expected = lever_device.cross(mapping.force_to_device(force_scene));
    EXPECT_NEAR((mapping.torque_to_device(lever_scene.cross(force_scene)) - expected).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace enteron::lcm
