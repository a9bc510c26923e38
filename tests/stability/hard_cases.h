// SPDX-License-Identifier: Apache-2.0
// The hard cases of the stability suite (see hard_cases.cpp for each one and its bounds).
#pragma once

#include <vector>

#include "stability_run.h"

namespace stability {

const std::vector<HardCase>& hard_cases();

}  // namespace stability
