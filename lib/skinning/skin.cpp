// SPDX-License-Identifier: Apache-2.0
#include "skinning/skin.h"

#include "skinning/axis_samples.h"
#include "skinning/convolution_skin.h"
#include "skinning/point_skeleton_skin.h"
#include "skinning/tube_skin.h"

namespace enteron::skinning {

void Skin::update(const double* points_xyz, std::size_t count) {
    points_.assign(points_xyz, points_xyz + 3 * count);
    table_.build(points_.data(), count);
    if (!(reference_length_ > 0.0)) reference_length_ = table_.total_length();
    topology_changed_ = false;
    rebuild();
    if (topology_changed_) ++topology_changes_;
}

std::size_t Skin::ring_intervals(double length) const {
    return AxisSamples::intervals_for(settings_.stable_topology ? reference_length_ : length, settings_.ring_spacing);
}

std::unique_ptr<Skin> make_skin(const SkinSettings& settings) {
    switch (settings.method) {
        case SkinMethod::tube: return std::make_unique<TubeSkin>(settings);
        case SkinMethod::point_skeleton: return std::make_unique<PointSkeletonSkin>(settings);
        case SkinMethod::convolution:
        default: return std::make_unique<ConvolutionSkin>(settings);
    }
}

}  // namespace enteron::skinning
