// SPDX-License-Identifier: Apache-2.0
// The parametric generalised cylinder: rings of radius R (each its own with a radius
// profile, tube_radius.h) on rotation-minimising frames,
// spaced evenly in arc length, closed by hemispherical caps. The fast baseline. At a bend
// tighter than R the rings on the inner side would cross each other (the surface folding
// over itself, the artefact France et al. name): each ray stops short of its neighbouring
// rings' planes instead (fold_over_limit.h), and the inner side becomes a crease. The two
// legs of a tight fold interpenetrate rather than meet: the tube has no contact surfaces
// (they would cost several times its whole update; docs/skinning.md).
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
