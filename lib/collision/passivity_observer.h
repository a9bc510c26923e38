// SPDX-License-Identifier: Apache-2.0
// A tool's passivity observer and limiter (Hannaford and Ryu, "Time-domain passivity
// control of haptic interfaces", IEEE Trans. Robotics and Automation 18(1), 2002). The
// tool's port is the commanded pose and the wrench rendered on the device: in a step where
// the tip moved by dx and turned by dtheta (axis times angle) under the wrench (F, tau) on
// the tool, the tool did the work W = -(F . dx + tau . dtheta) on the scene. The observer
// sums what went in (W > 0) and what came back (W < 0) since the tool was made; the scene
// is passive at the port while their balance stays >= 0.
//
// The limiter (off by default) is the time-domain passivity controller: when a step would
// take the balance below zero, a damper on the port takes out the difference. Its force
// opposes the motion, -lambda dx / |dx| with lambda = deficit / |dx|, as far as the force
// stays within max_force; the torque opposes the turn with what the force could not take.
// The balance then stays >= 0 exactly; the price is a force that is no longer what the
// bowel received (a drag against the motion whenever the scene would give energy back).
#pragma once

#include "base/geometry.h"
#include "base/state_io.h"
#include "collision/tool.h"

namespace enteron::collision {

class PassivityObserver {
public:
    // One accepted step: returns the wrench to render, `wrench` itself unless the limiter
    // is on and has to take energy out. Counts its work and the change of the force.
    ToolWrench observe(const ToolWrench& wrench, const Vec3& displacement, const Vec3& rotation, double max_force,
                       bool limit);

    const ToolStats& stats() const { return stats_; }
    double balance() const { return stats_.energy_in - stats_.energy_out; }

    // Its counters and the last force rendered (a section's part: the tools' section).
    void save_state(StateWriter& out) const;
    // Into `into` (checked and copied by the caller).
    static void restore_state(StateReader& in, PassivityObserver& into);

private:
    ToolStats stats_;
    Vec3 last_force_ = Vec3::Zero();
};

// The rotation (axis times angle, rad) that turns the unit quaternion `from` into `to`
// (w x y z), along the shorter arc.
Vec3 rotation_between(const std::array<double, 4>& from, const std::array<double, 4>& to);

}  // namespace enteron::collision
