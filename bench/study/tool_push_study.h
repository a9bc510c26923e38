#pragma once

#include "study_common.h"

namespace study {

// Writes collision_tool.csv: a tool pushed into the settled pile, against the sphere
// spacing and the contact stiffness.
void run_tool_push_study(const Options& options);

}  // namespace study
