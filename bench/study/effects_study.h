// SPDX-License-Identifier: Apache-2.0
#pragma once

#include "study_common.h"

namespace study {

void run_effects_study(const Options& options);

}  // namespace study
