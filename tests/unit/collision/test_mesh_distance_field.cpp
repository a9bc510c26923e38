// SPDX-License-Identifier: Apache-2.0
// A mesh obstacle's signed distance field (lib/collision/mesh_distance_field.h) against
// analytic shapes: a sphere mesh's field is |p - c| - r within the mesh's own facet error
// plus the trilinear interpolation's, its normal the radial direction, negative inside; a
// box's (flat faces: the mesh is the shape) is the box's exact signed distance within the
// interpolation error, and with `refine` exact near its faces; a cavity is solid outside its
// grid; far points are left out of sample_within; a grid too fine is refused with the
// voxel size that would fit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "base/error.h"
#include "collision/environment_force.h"
#include "collision/mesh_distance_field.h"
#include "collision/obstacle.h"
#include "collision/mesh_fixtures.h"

namespace enteron::collision {
namespace {

using collision_test::to_triangle_mesh;
std::pmr::memory_resource* const kMeshDistanceFieldMemory = std::pmr::new_delete_resource();

// The signed distance of an axis-aligned box about the origin with half extents h.
double box_distance(const Vec3& p, const Vec3& h) {
    const Vec3 q = p.cwiseAbs() - h;
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

TEST(MeshDistanceField, ASphereMeshsFieldIsTheSpheresDistance) {
    const double c[3] = {0.0, 0.0, 0.0}, r = 0.05;
    const TriangleMesh mesh = to_triangle_mesh(test_meshes::icosphere(c, r, 3));  // 1280 faces
    const double voxel = 0.002;
    const MeshDistanceField field(mesh, {voxel, 0.015, false}, kMeshDistanceFieldMemory);
    EXPECT_TRUE(field.report().closed());
    EXPECT_FALSE(field.outside_is_solid());
    // The inscribed mesh lies inside the sphere by at most r (1 - cos(edge angle / 2)).
    const double facet_error = 0.0005;
    std::mt19937_64 random(5);
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> offset(-0.012, 0.012);
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3 direction = Vec3(gauss(random), gauss(random), gauss(random)).normalized();
        const Vec3 p = (r + offset(random)) * direction;
        const double expected = p.norm() - r;
        EXPECT_NEAR(field.distance(p), expected, facet_error + 0.1 * voxel) << p.transpose();
        MeshDistanceField::Sample sample;
        ASSERT_TRUE(field.sample_within(p, 0.015, &sample));
        EXPECT_NEAR(sample.distance, expected, facet_error + 0.1 * voxel);
        EXPECT_GT(sample.normal.dot(direction), std::cos(10.0 * kPi / 180.0)) << "radial within 10 degrees";
        EXPECT_NEAR(sample.normal.norm(), 1.0, 1e-9);
    }
    EXPECT_LT(field.distance(Vec3::Zero()), -r + facet_error) << "deep inside: negative, a radius deep";
    EXPECT_NEAR(field.distance(Vec3(0.3, 0.0, 0.0)), 0.25, 0.01) << "beyond the grid it grows with the distance";
    MeshDistanceField::Sample far;
    EXPECT_FALSE(field.sample_within(Vec3(0.2, 0.0, 0.0), 0.01, &far));
}

TEST(MeshDistanceField, ABoxsFieldIsTheBoxsDistanceAndExactWhenRefined) {
    const double c[3] = {0.0, 0.0, 0.0}, half[3] = {0.04, 0.03, 0.02};
    const Vec3 h(half[0], half[1], half[2]);
    const TriangleMesh mesh = to_triangle_mesh(test_meshes::box(c, half, false));
    const double voxel = 0.004;
    const MeshDistanceField coarse(mesh, {voxel, 0.012, false}, kMeshDistanceFieldMemory);
    const MeshDistanceField refined(mesh, {voxel, 0.012, true}, kMeshDistanceFieldMemory);
    std::mt19937_64 random(8);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int near = 0, exact = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Vec3 p(0.05 * u(random), 0.04 * u(random), 0.03 * u(random));
        const double expected = box_distance(p, h);
        // The signed distance is piecewise linear except near edges and corners: the
        // trilinear error is a fraction of a voxel.
        EXPECT_NEAR(coarse.distance(p), expected, 0.3 * voxel) << p.transpose();
        // Refined near the surface: exact wherever a corner of the cell knows the closest
        // face (nearly everywhere); elsewhere the distance to a real face of the mesh, so
        // never closer than the surface is.
        MeshDistanceField::Sample sample;
        if (std::fabs(expected) < 0.004 && refined.sample_within(p, 0.012, &sample)) {
            near += 1;
            exact += std::fabs(sample.distance - expected) < 1e-9 ? 1 : 0;
            EXPECT_GE(std::fabs(sample.distance), std::fabs(expected) - 1e-12) << p.transpose();
            EXPECT_EQ(sample.distance < 0.0, expected < 0.0) << p.transpose();
        }
    }
    EXPECT_GT(near, 300);
    EXPECT_GT(exact, near * 95 / 100);
    MeshDistanceField::Sample on_top;
    ASSERT_TRUE(refined.sample_within(Vec3(0.01, 0.005, 0.025), 0.012, &on_top));
    EXPECT_LT((on_top.normal - Vec3::UnitZ()).norm(), 1e-9);
}

TEST(MeshDistanceField, PreparedForATaperedTubeTheGridStaysTheLargestRadiusAndTheThinSpheresReadExactly) {
    // A tube tapering from 3.5 to 1.3 cm: the grid a quarter of 3.5 cm as without a profile
    // (a quarter of 1.3 cm would take 20 times the voxels), read exactly near the surface,
    // where the thin spheres' contacts are, instead of by interpolation.
    const double c[3] = {0.0, 0.0, 0.0}, half[3] = {0.08, 0.06, 0.05};
    const Vec3 h(half[0], half[1], half[2]);
    enteron::collision::Obstacle constant, tapered;
    constant.kind = tapered.kind = enteron::collision::ObstacleKind::mesh;
    constant.mesh = tapered.mesh =
        std::make_shared<const enteron::collision::TriangleMesh>(to_triangle_mesh(test_meshes::box(c, half, false)));
    enteron::collision::EnvironmentForce::prepare(constant, 0.035, kMeshDistanceFieldMemory);
    enteron::collision::EnvironmentForce::prepare(tapered, 0.035, kMeshDistanceFieldMemory, 0.013);
    const double voxel = enteron::collision::kDefaultVoxelRadii * 0.035;
    EXPECT_EQ(tapered.field->settings().voxel_size, voxel);
    EXPECT_EQ(tapered.field->settings().band, constant.field->settings().band);
    EXPECT_FALSE(constant.field->settings().refine);
    ASSERT_TRUE(tapered.field->settings().refine);
    std::mt19937_64 random(28);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int near = 0, exact = 0;
    double interpolated_worst = 0.0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Vec3 p(0.1 * u(random), 0.08 * u(random), 0.07 * u(random));
        const double expected = box_distance(p, h);
        MeshDistanceField::Sample thin, wide;
        if (!(expected > 0.0 && expected < 0.013)) continue;  // where a thin sphere's centre touches
        if (!tapered.field->sample_within(p, 0.013, &thin) || !constant.field->sample_within(p, 0.013, &wide)) continue;
        near += 1;
        exact += std::fabs(thin.distance - expected) < 1e-9 ? 1 : 0;
        interpolated_worst = std::max(interpolated_worst, std::fabs(wide.distance - expected));
    }
    EXPECT_GT(near, 200);
    EXPECT_GT(exact, near * 95 / 100);
    EXPECT_GT(interpolated_worst, 1e-4) << "the interpolated field departs from the box near its edges";
}

TEST(MeshDistanceField, ACavityIsSolidOutsideItsWalls) {
    const double c[3] = {0.0, 0.0, 0.0}, half[3] = {0.1, 0.08, 0.06};
    const MeshDistanceField cavity(to_triangle_mesh(test_meshes::box(c, half, true)), {0.005, 0.015, false}, kMeshDistanceFieldMemory);
    EXPECT_TRUE(cavity.outside_is_solid());
    EXPECT_GT(cavity.report().signed_volume, -1.0);
    EXPECT_LT(cavity.report().signed_volume, 0.0);
    EXPECT_NEAR(cavity.distance(Vec3(0.0, 0.0, 0.05)), 0.01, 0.002) << "the bowel's side: inside the walls";
    EXPECT_LT(cavity.distance(Vec3(0.0, 0.0, 0.2)), 0.0) << "beyond the walls: in the solid";
}

TEST(MeshDistanceField, AGridTooFineIsRefinedWithTheVoxelSizeThatFits) {
    const double c[3] = {0.0, 0.0, 0.0}, half[3] = {0.5, 0.5, 0.5};
    try {
        MeshDistanceField field(to_triangle_mesh(test_meshes::box(c, half, false)), {1e-4, 0.01, false}, kMeshDistanceFieldMemory);
        ADD_FAILURE() << "built " << field.voxel_count() << " voxels";
    } catch (const Error& error) {
        EXPECT_EQ(error.code(), ErrorCode::invalid_argument);
        const std::string message = error.what();
        EXPECT_NE(message.find("a voxel size of 0.0001 m over this mesh (1.02 m across) needs"), std::string::npos) << message;
        EXPECT_NE(message.find("give a voxel size of at least 0.003"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace enteron::collision
