// SPDX-License-Identifier: Apache-2.0
#pragma once

#include "study_common.h"

namespace study {

// Writes collision_tool.csv: a tool pushed into the settled pile, against the sphere
// spacing and the contact stiffness.
void run_tool_push_study(const Options& options);

// --run NAME (study_runs.h): computes that tool run and prints its record; false if NAME
// is not a tool run.
bool print_tool_run(const Options& options, const std::string& name);

}  // namespace study
