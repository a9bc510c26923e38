// SPDX-License-Identifier: Apache-2.0
#pragma once

#include "study_common.h"

namespace study {

void run_skin_study(const Options& options);

}  // namespace study
