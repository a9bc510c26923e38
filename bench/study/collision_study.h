#pragma once

#include "study_common.h"

namespace study {

void run_collision_study(const Options& options);

}  // namespace study
