// SPDX-License-Identifier: Apache-2.0
// The tool hard cases' drivers: a tool sweeping back and forth through the bowel, a grasp
// yanked far past the tool's max_force, a tool teleported inside the bowel. Each drives
// tool 0 of its scene (vertical: identity orientation) and accounts for its work.
#pragma once

#include <memory>

#include "stability_run.h"

namespace stability {

// Sweeps the tip along x between x_min and x_max at `speed` (m/s), at the height and y of
// `tip`. Work of a step: F . dx, F the force on the bowel at the end of the step (minus the
// wrench) and dx the tip's displacement: an estimate, the force varies within the step.
std::unique_ptr<ToolDriver> make_sweep(double speed_m_per_s, double x_min_m, double x_max_m, const double tip_m[3]);

// Cycles every `period_s`: the tip goes, in one step, to rest on a control point (a different
// one each cycle) and grasps there, then is pulled straight up at `speed` (m/s) for `pull_s`
// seconds (far more than a max_force-bounded grasp can follow: it slips), and waits. Work:
// as the sweep, but the bound max_force |dx| for the step back down, which may cross the bowel.
std::unique_ptr<ToolDriver> make_yank(double period_s, double speed_m_per_s, double pull_s, double max_force_N);

// Every `period_s` puts the tip, within one step, on a control point (a different one each
// time): the tool crosses the bowel to get there, in one step. Work of a step: the bound
// max_force |dx| (the tool's forces on the bowel add up to at most max_force).
std::unique_ptr<ToolDriver> make_teleport(double period_s, double max_force_N);

}  // namespace stability
