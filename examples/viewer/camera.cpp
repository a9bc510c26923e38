// SPDX-License-Identifier: Apache-2.0
#include "camera.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace viewer {

namespace {
constexpr double kOrbitRadPerPx = 0.006;
constexpr double kScopeRollRadPerPx = 0.01;
constexpr double kScopeSlidePerNotch = 0.01;  // m
constexpr double kScopeMaxInsertion = 0.3;    // m
constexpr double kMaxPitchRad = 1.55;  // just short of straight down, where yaw is undefined
constexpr double kZoomPerNotch = 0.9;
}  // namespace

void Camera::frame(const Eigen::Vector3d& center, double size_m) {
    target_ = center;
    // The cube's bounding sphere (radius size sqrt(3)/2) about fills the height.
    distance_ = 0.95 * 0.5 * std::sqrt(3.0) * size_m / std::sin(0.5 * fov_y_rad_);
    yaw_rad_ = -1.5707963267948966;
    pitch_rad_ = 0.75;
}

namespace {
// A unit vector across the shaft: the optics' tilt at roll 0 is toward -z (the patient's
// back), or toward +y where the shaft is nearly vertical.
Eigen::Vector3d across(const Eigen::Vector3d& shaft) {
    const Eigen::Vector3d toward = std::abs(shaft.z()) < 0.99 ? Eigen::Vector3d(-Eigen::Vector3d::UnitZ())
                                                              : Eigen::Vector3d(Eigen::Vector3d::UnitY());
    return (toward - toward.dot(shaft) * shaft).normalized();
}
}  // namespace

void Camera::look_through_scope(const Eigen::Vector3d& port, const Eigen::Vector3d& target, double insertion_m) {
    scope_ = true;
    port_ = port;
    insertion_m_ = std::clamp(insertion_m, 0.0, kScopeMaxInsertion);
    // Aim the shaft 30 degrees off the line to the target, on the side away from the optics'
    // tilt, so that the view looks at the target (exactly as the tip nears the port).
    const Eigen::Vector3d sight = (target - port).normalized();
    const Eigen::Vector3d tilt = across(sight);
    shaft_ = (std::cos(kScopeAngleRad) * sight - std::sin(kScopeAngleRad) * tilt).normalized();
    // Turn the optics so that their tilt points back toward the target.
    const Eigen::Vector3d base = across(shaft_), side = shaft_.cross(base);
    const Eigen::Vector3d wanted = (sight - sight.dot(shaft_) * shaft_).normalized();
    optics_roll_rad_ = std::atan2(wanted.dot(side), wanted.dot(base));
}

void Camera::orbit(double dx_px, double dy_px) {
    if (scope_) {  // the shaft pivots about the port
        const Eigen::Vector3d side = shaft_.cross(Eigen::Vector3d::UnitZ()).norm() > 1e-6
                                         ? Eigen::Vector3d(shaft_.cross(Eigen::Vector3d::UnitZ()).normalized())
                                         : Eigen::Vector3d(Eigen::Vector3d::UnitX());
        const Eigen::Matrix3d turn = (Eigen::AngleAxisd(-kOrbitRadPerPx * dx_px, Eigen::Vector3d::UnitZ()) *
                                      Eigen::AngleAxisd(-kOrbitRadPerPx * dy_px, side))
                                         .toRotationMatrix();
        shaft_ = (turn * shaft_).normalized();
        return;
    }
    yaw_rad_ -= kOrbitRadPerPx * dx_px;
    pitch_rad_ = std::clamp(pitch_rad_ + kOrbitRadPerPx * dy_px, -kMaxPitchRad, kMaxPitchRad);
}

void Camera::pan(double dx_px, double dy_px, int viewport_height_px) {
    if (scope_) {  // the optics turn about the shaft: the view sweeps its cone
        optics_roll_rad_ += kScopeRollRadPerPx * dx_px;
        return;
    }
    // Drag the target plane with the mouse: one pixel is this many metres at the target.
    const double metres_per_px = 2.0 * distance_ * std::tan(0.5 * fov_y_rad_) / std::max(1, viewport_height_px);
    target_ += metres_per_px * (-dx_px * right() + dy_px * up());
}

void Camera::zoom(double notches) {
    if (scope_) {  // the scope slides through its port
        insertion_m_ = std::clamp(insertion_m_ + kScopeSlidePerNotch * notches, 0.0, kScopeMaxInsertion);
        return;
    }
    distance_ = std::clamp(distance_ * std::pow(kZoomPerNotch, notches), 1e-3, 1e3);
}

Eigen::Vector3d Camera::eye() const {
    if (scope_) return port_ + insertion_m_ * shaft_;
    const Eigen::Vector3d offset(std::cos(pitch_rad_) * std::cos(yaw_rad_), std::cos(pitch_rad_) * std::sin(yaw_rad_),
                                 std::sin(pitch_rad_));
    return target_ + distance_ * offset;
}

Eigen::Vector3d Camera::forward() const {
    if (!scope_) return (target_ - eye()).normalized();
    const Eigen::Vector3d base = across(shaft_), side = shaft_.cross(base);
    const Eigen::Vector3d tilt = std::cos(optics_roll_rad_) * base + std::sin(optics_roll_rad_) * side;
    return (std::cos(kScopeAngleRad) * shaft_ + std::sin(kScopeAngleRad) * tilt).normalized();
}
Eigen::Vector3d Camera::up_hint() const {
    return forward().cross(Eigen::Vector3d::UnitZ()).norm() > 1e-6 ? Eigen::Vector3d(Eigen::Vector3d::UnitZ())
                                                                   : Eigen::Vector3d(Eigen::Vector3d::UnitY());
}
Eigen::Vector3d Camera::right() const { return forward().cross(up_hint()).normalized(); }
Eigen::Vector3d Camera::up() const { return right().cross(forward()); }

Eigen::Matrix4f look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up_hint) {
    const Eigen::Vector3d f = (target - eye).normalized();
    const Eigen::Vector3d r = f.cross(up_hint).normalized();
    const Eigen::Vector3d u = r.cross(f);
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.block<1, 3>(0, 0) = r.transpose();
    m.block<1, 3>(1, 0) = u.transpose();
    m.block<1, 3>(2, 0) = -f.transpose();
    m(0, 3) = -r.dot(eye);
    m(1, 3) = -u.dot(eye);
    m(2, 3) = f.dot(eye);
    return m.cast<float>();
}

Eigen::Matrix4f Camera::view() const { return look_at(eye(), eye() + forward(), up_hint()); }

Eigen::Matrix4f Camera::projection(double aspect) const {
    // Near and far follow the distance, so depth precision follows the zoom; a scope sees
    // from 3 mm to a metre.
    const double near_m = scope_ ? 0.003 : 0.02 * distance_, far_m = scope_ ? 1.0 : 20.0 * distance_;
    const double f = 1.0 / std::tan(0.5 * fov_y_rad());
    Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
    m(0, 0) = f / aspect;
    m(1, 1) = f;
    m(2, 2) = (far_m + near_m) / (near_m - far_m);
    m(2, 3) = 2.0 * far_m * near_m / (near_m - far_m);
    m(3, 2) = -1.0;
    return m.cast<float>();
}

Ray Camera::ray(double x_px, double y_px, int width_px, int height_px) const {
    const double aspect = static_cast<double>(width_px) / std::max(1, height_px);
    const double half_height = std::tan(0.5 * fov_y_rad());
    const double x = 2.0 * x_px / std::max(1, width_px) - 1.0;
    const double y = 1.0 - 2.0 * y_px / std::max(1, height_px);
    Ray ray;
    ray.origin = eye();
    ray.direction = (forward() + x * half_height * aspect * right() + y * half_height * up()).normalized();
    return ray;
}

}  // namespace viewer
