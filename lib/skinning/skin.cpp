#include "skinning/skin.h"

#include "skinning/convolution_skin.h"
#include "skinning/point_skeleton_skin.h"
#include "skinning/tube_skin.h"

namespace enteron::skinning {

void Skin::update(const double* points_xyz, std::size_t count) {
    points_.assign(points_xyz, points_xyz + 3 * count);
    table_.build(points_.data(), count);
    rebuild();
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
