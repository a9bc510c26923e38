// SPDX-License-Identifier: Apache-2.0
#include "skinning/skin.h"

#include <utility>

#include "skinning/axis_samples.h"
#include "skinning/convolution_skin.h"
#include "skinning/point_skeleton_skin.h"
#include "skinning/tube_skin.h"

namespace enteron::skinning {

void Skin::keep_previous() {
    has_previous_ = !points_.empty();
    if (!has_previous_) return;
    // The table refers to its points' buffer: both move together.
    points_.swap(previous_points_);
    std::swap(table_, previous_table_);
    if (rebuilds_whole_mesh()) {
        std::swap(mesh_, previous_mesh_);
        return;
    }
    previous_mesh_.positions.assign(mesh_.positions.begin(), mesh_.positions.end());
    if (previous_indices_of_ != topology_changes_) {
        previous_mesh_.indices.assign(mesh_.indices.begin(), mesh_.indices.end());
        previous_mesh_.u.assign(mesh_.u.begin(), mesh_.u.end());
        previous_indices_of_ = topology_changes_;
    }
}

void Skin::update(const double* points_xyz, std::size_t count) {
    keep_previous();
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
