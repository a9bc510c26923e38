// SPDX-License-Identifier: Apache-2.0
#include "camera.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace viewer {

namespace {
constexpr double kOrbitRadPerPx = 0.006;
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

void Camera::orbit(double dx_px, double dy_px) {
    yaw_rad_ -= kOrbitRadPerPx * dx_px;
    pitch_rad_ = std::clamp(pitch_rad_ + kOrbitRadPerPx * dy_px, -kMaxPitchRad, kMaxPitchRad);
}

void Camera::pan(double dx_px, double dy_px, int viewport_height_px) {
    // Drag the target plane with the mouse: one pixel is this many metres at the target.
    const double metres_per_px = 2.0 * distance_ * std::tan(0.5 * fov_y_rad_) / std::max(1, viewport_height_px);
    target_ += metres_per_px * (-dx_px * right() + dy_px * up());
}

void Camera::zoom(double notches) { distance_ = std::clamp(distance_ * std::pow(kZoomPerNotch, notches), 1e-3, 1e3); }

Eigen::Vector3d Camera::eye() const {
    const Eigen::Vector3d offset(std::cos(pitch_rad_) * std::cos(yaw_rad_), std::cos(pitch_rad_) * std::sin(yaw_rad_),
                                 std::sin(pitch_rad_));
    return target_ + distance_ * offset;
}

Eigen::Vector3d Camera::forward() const { return (target_ - eye()).normalized(); }
Eigen::Vector3d Camera::right() const { return forward().cross(Eigen::Vector3d::UnitZ()).normalized(); }
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

Eigen::Matrix4f Camera::view() const { return look_at(eye(), target_, Eigen::Vector3d::UnitZ()); }

Eigen::Matrix4f Camera::projection(double aspect) const {
    // Near and far follow the distance, so depth precision follows the zoom.
    const double near_m = 0.02 * distance_, far_m = 20.0 * distance_;
    const double f = 1.0 / std::tan(0.5 * fov_y_rad_);
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
    const double half_height = std::tan(0.5 * fov_y_rad_);
    const double x = 2.0 * x_px / std::max(1, width_px) - 1.0;
    const double y = 1.0 - 2.0 * y_px / std::max(1, height_px);
    Ray ray;
    ray.origin = eye();
    ray.direction = (forward() + x * half_height * aspect * right() + y * half_height * up()).normalized();
    return ray;
}

}  // namespace viewer
