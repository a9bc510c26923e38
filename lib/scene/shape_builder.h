// SPDX-License-Identifier: Apache-2.0
// The initial control points of the axis: `count` points along the chosen shape, each at
// straight-line distance l0 = length / (count - 1) from the previous one, so every segment
// starts at its rest length (a straight line is exactly at rest; a curved shape starts
// with the tiny strain of a chord against its arc).
#pragma once

#include <cstddef>

#include "scene/scene_config.h"

namespace enteron::scene {

// Writes count x 3 coordinates (m) into out_xyz.
void build_shape(const ShapeConfig& shape, double length, std::size_t count, double* out_xyz);

}  // namespace enteron::scene
