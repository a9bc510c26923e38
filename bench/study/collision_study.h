// SPDX-License-Identifier: Apache-2.0
#pragma once

#include "study_common.h"

namespace study {

void run_collision_study(const Options& options);

// --run NAME (study_runs.h): computes that pile run and prints its record; false if NAME
// is not a collision run.
bool print_collision_run(const Options& options, const std::string& name);

}  // namespace study
