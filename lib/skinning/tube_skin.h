// SPDX-License-Identifier: Apache-2.0
// The parametric generalised cylinder: rings of radius R on rotation-minimising frames,
// spaced evenly in arc length, closed by hemispherical caps. The fast baseline. At a bend
// tighter than R the rings on the inner side cross each other (the surface folds over
// itself) and the two legs of a tight fold interpenetrate rather than meet: the artefacts
// France et al. name, which the metrics count (inverted triangles, normal deviation).
#pragma once

#include "skinning/axis_samples.h"
#include "skinning/ring_grid.h"
#include "skinning/rotation_minimizing_frames.h"
#include "skinning/skin.h"

namespace enteron::skinning {

class TubeSkin final : public Skin {
public:
    explicit TubeSkin(const SkinSettings& settings) : Skin(settings) {}

private:
    void rebuild() override;

    AxisSamples rings_;
    RotationMinimizingFrames frames_;
    RingGrid grid_;
};

}  // namespace enteron::skinning
