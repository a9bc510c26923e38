// SPDX-License-Identifier: Apache-2.0
#pragma once

#include "study_common.h"

namespace study {

// Writes mechanics.csv and mechanics_reference.csv into options.out_dir.
void run_mechanics_study(const Options& options);
// --run NAME (study_runs.h): computes that run and prints its record; false if NAME is not
// a mechanics run.
bool print_mechanics_run(const Options& options, const std::string& name);

}  // namespace study
