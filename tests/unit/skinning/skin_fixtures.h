// Shared by the skinning tests: the default radius and the default settings of each method.
#pragma once

#include <gtest/gtest.h>

#include "skinning/skin.h"
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

}  // namespace skin_test
