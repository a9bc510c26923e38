// SPDX-License-Identifier: Apache-2.0
// The radius a skin draws at each place along the axis: constant (SkinSettings::radius), or
// the scene's radius profile (spline/length_profile.h) read at the place's arc length at
// rest. A place is named by its spline parameter p (0 .. control points - 1), which maps
// linearly to rest arc length, s = p l0 (l0 the rest length of a segment), however the axis
// has stretched since: the skins sample the axis by its current arc length, look up the
// parameter there (spline::ArcLengthTable::parameter_at) and read the profile at p l0.
#pragma once

#include <memory>

#include "spline/length_profile.h"

namespace enteron::skinning {

struct TubeRadius {
    std::shared_ptr<const spline::LengthProfile> profile;  // null: the radius is constant
    double segment_rest_length = 0.0;                      // l0, m

    bool varies() const { return profile != nullptr; }
    // The radius at spline parameter p, m; `constant` without a profile.
    double at_parameter(double p, double constant) const {
        return profile ? profile->at(p * segment_rest_length) : constant;
    }
};

}  // namespace enteron::skinning
