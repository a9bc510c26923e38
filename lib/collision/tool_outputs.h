// SPDX-License-Identifier: Apache-2.0
// What a tool reports (tool.h's ToolOutput): the wrench of each accepted step is exactly minus
// what the bowel received over it. The integrator tells the tools how it used each evaluation
// (DrivenEffect::evaluation_used), and each tool adds what the bowel received from that
// evaluation to the sums of its attempt: the forces at the end of an implicit substep
// (F - H dq - C dv, H and C the contacts' linearisation) or the explicit evaluations with
// their weights, times their duration. Evaluating the law again at the start-of-step
// velocities instead reported a friction the bowel never received: the click at every
// reversal (issue 18). When a step is accepted its sums become the tool's outputs, the wrench
// through the passivity observer (passivity_observer.h).
#pragma once

#include <cstdint>

#include "base/geometry.h"
#include "collision/contact_log.h"
#include "collision/tool.h"
#include "collision/tool_contacts.h"
#include "collision/tool_state.h"
#include "mechanics/state.h"

namespace enteron::collision {

// Adds what the bowel received from tool `index`'s contacts of the last evaluation (in
// `contacts`), which acted for `duration` seconds, to the attempt's sums. An implicit
// evaluation gives `after`, the state at the substep's end, and `proxy_move`, the proxy's
// motion over it as the implicit step solved it with the bowel (zero without a proxy body).
// The sphere contacts go into `log`, with the force the bowel received.
void add_evaluation_received(ToolState& tool, uint32_t index, const ToolContacts& contacts, double duration,
                             const mechanics::State* after, const Vec3& proxy_move, ContactLog& log);

// The accepted step's outputs from its attempt's sums: the wrench (minus the mean force the
// bowel received, within max_force, through the passivity observer for the commanded motion
// from tool.current to tool.target), the stiffness and contacts of the last evaluation used,
// the contacts' impulse.
void accept_outputs(ToolState& tool);

// What a tool publishes (a tool not removed).
void write_output(const ToolState& tool, ToolOutput& output);

}  // namespace enteron::collision
