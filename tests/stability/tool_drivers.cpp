// SPDX-License-Identifier: Apache-2.0
#include "tool_drivers.h"

#include <cmath>
#include <limits>
#include <vector>

namespace stability {

namespace {

constexpr int32_t kDrivenTool = 0;
const double kVertical[4] = {1.0, 0.0, 0.0, 0.0};  // identity: the shaft rises from the tip
const double kFailed = std::numeric_limits<double>::quiet_NaN();

// Control point `index` of the published state, or false.
bool control_point(const ent_scene* scene, uint32_t index, double out[3]) {
    uint32_t count = 0;
    if (ent_scene_control_points(scene, 0, nullptr, &count) != ENT_OK) return false;
    std::vector<double> points(3 * std::size_t{count});
    if (ent_scene_control_points(scene, count, points.data(), &count) != ENT_OK) return false;
    for (int c = 0; c < 3; ++c) out[c] = points[3 * std::size_t{index % count} + c];
    return true;
}

// Keeps the tip where it was told to go, the displacement of the coming step, and the
// estimate of a step's work from the wrench at its end.
class MovingTip : public ToolDriver {
protected:
    bool move_to(ent_scene* scene, const double target[3]) {
        for (int c = 0; c < 3; ++c) {
            step_[c] = target[c] - tip_[c];
            tip_[c] = target[c];
        }
        return ent_tool_set_pose(scene, kDrivenTool, tip_, kVertical) == ENT_OK;
    }
    // F . dx with F = minus the wrench: the force on the bowel at the end of the step.
    double wrench_work(const ent_scene* scene) const {
        double force[3], torque[3];
        if (ent_tool_wrench(scene, kDrivenTool, force, torque) != ENT_OK) return kFailed;
        return -(force[0] * step_[0] + force[1] * step_[1] + force[2] * step_[2]);
    }
    double step_length() const { return std::sqrt(step_[0] * step_[0] + step_[1] * step_[1] + step_[2] * step_[2]); }

    double tip_[3] = {0.0, 0.0, 0.0};
    double step_[3] = {0.0, 0.0, 0.0};
};

class Sweep : public MovingTip {
public:
    Sweep(double speed, double x_min, double x_max, const double tip[3])
        : speed_(speed), x_min_(x_min), x_max_(x_max) {
        for (int c = 0; c < 3; ++c) tip_[c] = tip[c];
    }
    bool before_step(ent_scene* scene, double time_s) override {
        // A triangle wave: x_min -> x_max -> x_min at `speed`.
        const double span = x_max_ - x_min_;
        const double phase = std::fmod(speed_ * time_s, 2.0 * span);
        double target[3] = {tip_[0], tip_[1], tip_[2]};
        target[0] = phase < span ? x_min_ + phase : x_max_ - (phase - span);
        return move_to(scene, target);
    }
    double work_of_step(const ent_scene* scene) override { return wrench_work(scene); }

private:
    double speed_, x_min_, x_max_;
};

class Yank : public MovingTip {
public:
    Yank(double period, double speed, double pull, double max_force)
        : period_(period), speed_(speed), pull_(pull), max_force_(max_force) {}
    bool before_step(ent_scene* scene, double time_s) override {
        const long cycle = static_cast<long>(std::floor(time_s / period_ + 1e-9));
        const double in_cycle = time_s - cycle * period_;
        returning_ = cycle != cycle_;
        if (returning_) {
            // A new cycle: release, and back down to the next control point in one step.
            cycle_ = cycle;
            grasped_ = false;
            if (ent_tool_release(scene, kDrivenTool) != ENT_OK) return false;
            double point[3];
            if (!control_point(scene, static_cast<uint32_t>(37 * cycle + 11), point)) return false;
            point[2] += 0.015;  // resting on the bowel (R + tool radius = 17.5 mm)
            return move_to(scene, point);
        }
        if (!grasped_) {
            grasped_ = true;
            if (ent_tool_grasp(scene, kDrivenTool) != ENT_OK) return false;
        }
        double target[3] = {tip_[0], tip_[1], tip_[2]};
        if (in_cycle < pull_) target[2] += speed_ * (time_s - last_time_);
        last_time_ = time_s;
        return move_to(scene, target);
    }
    // The step back down may cross the bowel: the bound max_force |dx| there.
    double work_of_step(const ent_scene* scene) override {
        return returning_ ? max_force_ * step_length() : wrench_work(scene);
    }

private:
    double period_, speed_, pull_, max_force_;
    bool returning_ = false;
    long cycle_ = -1;
    bool grasped_ = false;
    double last_time_ = 0.0;
};

class Teleport : public MovingTip {
public:
    Teleport(double period, double max_force) : period_(period), max_force_(max_force) {}
    bool before_step(ent_scene* scene, double time_s) override {
        const long jump = static_cast<long>(std::floor(time_s / period_ + 1e-9));
        if (jump == jump_) {
            for (double& d : step_) d = 0.0;
            return true;  // the tool stays where it is: a still tool does no work
        }
        jump_ = jump;
        double point[3];
        if (!control_point(scene, static_cast<uint32_t>(53 * jump + 7), point)) return false;
        return move_to(scene, point);  // the tip on the axis: the tool deep inside the bowel
    }
    double work_of_step(const ent_scene*) override { return max_force_ * step_length(); }

private:
    double period_, max_force_;
    long jump_ = -1;
};

}  // namespace

std::unique_ptr<ToolDriver> make_sweep(double speed_m_per_s, double x_min_m, double x_max_m, const double tip_m[3]) {
    return std::make_unique<Sweep>(speed_m_per_s, x_min_m, x_max_m, tip_m);
}

std::unique_ptr<ToolDriver> make_yank(double period_s, double speed_m_per_s, double pull_s, double max_force_N) {
    return std::make_unique<Yank>(period_s, speed_m_per_s, pull_s, max_force_N);
}

std::unique_ptr<ToolDriver> make_teleport(double period_s, double max_force_N) {
    return std::make_unique<Teleport>(period_s, max_force_N);
}

}  // namespace stability
