// Distance surface of point skeletons (France et al. 2002, section 3), polygonised by
// marching cubes on a narrow band.
//
// Skeleton points lie on the axis evenly in arc length (their number follows the length,
// so stretching adds points instead of spreading them, and the radius does not pulse).
// Each contributes the compact kernel g(d) = (1 - d^2 / Rs^2)^3 weighted by the spacing,
// so the field is a Riemann sum of a line integral and does not depend on the spacing.
// Blending is limited to axis neighbours: a point of space sums only the skeleton points
// within D (the window) in arc length of its nearest skeleton point. Rs^2 = R^2 + D^2, so
// at the surface the window's edge contributes nothing and the field is continuous there.
// Beyond an end the field is made radial around the end point (a hemispherical cap), and
// points continue straight past the ends so the window is full up to them.
//
// Only the voxels within R + 2 voxels of a skeleton point are visited (sparse blocks, see
// sparse_voxel_grid.h). Each marching-cubes vertex is then projected onto the iso-surface
// by Newton steps on the field, its normal is the field gradient and its u the projection
// of the vertex on the axis next to its nearest skeleton point.
#pragma once

#include <vector>

#include "skinning/axis_samples.h"
#include "skinning/marching_cubes.h"
#include "skinning/skin.h"
#include "skinning/sparse_voxel_grid.h"

namespace enteron::skinning {

class PointSkeletonSkin final : public Skin {
public:
    explicit PointSkeletonSkin(const SkinSettings& settings);

    double iso_value() const { return iso_; }
    std::size_t skeleton_points() const { return skeleton_.intervals() + 1; }
    std::size_t band_blocks() const { return grid_.block_count(); }
    std::size_t cells_visited() const { return cubes_.cells_visited(); }

private:
    void rebuild() override;
    // Field and gradient at p for the window around skeleton point k (an index into
    // skeleton_, real points only).
    double field(Vec3 p, std::size_t k, Vec3* gradient) const;
    // The real skeleton point nearest to p, searching from k along the axis.
    std::size_t nearest_from(Vec3 p, std::size_t k) const;
    void splat();

    double iso_ = 0.0;
    double support2_ = 0.0;  // Rs^2
    std::size_t window_points_ = 0;
    AxisSamples skeleton_;
    SparseVoxelGrid grid_;
    MarchingCubes cubes_;
    std::vector<int32_t> seeds_;
};

}  // namespace enteron::skinning
