// SPDX-License-Identifier: Apache-2.0
// Shared by the skinning tests: the default radius, the default settings of each method,
// and a skin updated on an axis and measured against the ideal tube.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "skinning/skin.h"
#include "skinning/skin_metrics.h"
#include "skinning/skin_settings.h"

namespace skin_test {

using enteron::skinning::SkinMethod;
using enteron::skinning::SkinSettings;

constexpr double R = 0.0125;

// The defaults of ent_skin_desc_default, in metres.
inline SkinSettings defaults(SkinMethod method) {
    SkinSettings s;
    s.method = method;
    s.radius = R;
    s.segments = 16;
    s.ring_spacing = 0.5 * R;
    s.cap_rings = 4;
    s.skeleton_spacing = 0.25 * R;
    s.voxel_size = R / 3.0;
    s.window = R;
    return s;
}

// Updates `skin` on the axis of control points q (x y z each) and measures its mesh.
inline enteron::skinning::SkinMetrics skin_and_measure(enteron::skinning::Skin& skin, const std::vector<double>& q) {
    skin.update(q.data(), q.size() / 3);
    return enteron::skinning::measure_skin(skin.mesh(), skin.axis_points(), skin.axis_count(), skin.arc_length(), R);
}

}  // namespace skin_test
