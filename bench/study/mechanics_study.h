#pragma once

#include "study_common.h"

namespace study {

// Writes mechanics.csv and mechanics_reference.csv into options.out_dir.
void run_mechanics_study(const Options& options);

}  // namespace study
