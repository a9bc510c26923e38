// SPDX-License-Identifier: Apache-2.0
// An orbit camera, z up (gravity is -z in the scenes): it looks at a target from a
// distance, turned by yaw about z and tilted by pitch above the horizon. Orbit, pan and
// zoom take mouse motion in pixels; ray() gives the line of sight through a pixel, which
// is how the mouse reaches into the scene.
//
// Or a laparoscope (look_through_scope): a rigid 30-degree scope through a port in the
// abdominal wall. Its shaft pivots about the port (orbit), slides in and out (zoom), and
// its optics turn about the shaft (pan), so that the view, 30 degrees off the shaft,
// sweeps a cone as a surgeon's does; the image stays upright (the camera head is held
// level while the optics turn). Its field of view is 70 degrees and its light sits at its
// tip (renderer.h).
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

    // The laparoscope through `port`, its tip inserted `insertion_m` along the shaft, the shaft
    // aimed so that the optics look at `target`.
    void look_through_scope(const Eigen::Vector3d& port, const Eigen::Vector3d& target, double insertion_m);
    void leave_scope() { scope_ = false; }
    bool scope() const { return scope_; }
    const Eigen::Vector3d& port() const { return port_; }
    static constexpr double kScopeAngleRad = 0.5235987755982988;  // 30 degrees between shaft and view

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
    double fov_y_rad() const { return scope_ ? kScopeFovYRad : fov_y_rad_; }
    // The line of sight through pixel (x, y) of a w x h viewport, (0, 0) at the top left.
    Ray ray(double x_px, double y_px, int width_px, int height_px) const;

private:
    static constexpr double kScopeFovYRad = 1.2217304763960306;  // 70 degrees
    // The image's up: +z, or +y where the view is nearly vertical.
    Eigen::Vector3d up_hint() const;

    Eigen::Vector3d target_ = Eigen::Vector3d::Zero();
    double distance_ = 0.6;       // m
    double yaw_rad_ = -1.5707963267948966;  // eye on -y: x to the right, z up
    double pitch_rad_ = 0.75;     // eye above the target, looking down 43 degrees
    double fov_y_rad_ = 0.6981317007977318;  // 40 degrees
    // The laparoscope.
    bool scope_ = false;
    Eigen::Vector3d port_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d shaft_ = -Eigen::Vector3d::UnitZ();  // unit, from the port inward
    double insertion_m_ = 0.03;
    double optics_roll_rad_ = 0.0;  // the optics turned about the shaft
};

}  // namespace viewer
