// SPDX-License-Identifier: Apache-2.0
// An orbit camera, z up (gravity is -z in the scenes): it looks at a target from a
// distance, turned by yaw about z and tilted by pitch above the horizon. Orbit, pan and
// zoom take mouse motion in pixels; ray() gives the line of sight through a pixel, which
// is how the mouse reaches into the scene.
#pragma once

#include <Eigen/Core>

namespace viewer {

struct Ray {
    Eigen::Vector3d origin;
    Eigen::Vector3d direction;  // unit
};

// The view matrix of an eye looking at target, up_hint roughly up (OpenGL's convention:
// the eye looks down its -z).
Eigen::Matrix4f look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up_hint);

class Camera {
public:
    // Looks at center from the front (-y) and above, far enough to see a cube of size_m.
    void frame(const Eigen::Vector3d& center, double size_m);

    void orbit(double dx_px, double dy_px);
    void pan(double dx_px, double dy_px, int viewport_height_px);
    void zoom(double notches);  // > 0: closer

    Eigen::Vector3d eye() const;
    Eigen::Vector3d forward() const;  // unit, from the eye toward the target
    Eigen::Vector3d right() const;    // unit
    Eigen::Vector3d up() const;       // unit
    double distance() const { return distance_; }
    const Eigen::Vector3d& target() const { return target_; }

    Eigen::Matrix4f view() const;
    Eigen::Matrix4f projection(double aspect) const;
    // The line of sight through pixel (x, y) of a w x h viewport, (0, 0) at the top left.
    Ray ray(double x_px, double y_px, int width_px, int height_px) const;

private:
    Eigen::Vector3d target_ = Eigen::Vector3d::Zero();
    double distance_ = 0.6;       // m
    double yaw_rad_ = -1.5707963267948966;  // eye on -y: x to the right, z up
    double pitch_rad_ = 0.75;     // eye above the target, looking down 43 degrees
    double fov_y_rad_ = 0.6981317007977318;  // 40 degrees
};

}  // namespace viewer
