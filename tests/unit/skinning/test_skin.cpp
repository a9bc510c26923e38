// SPDX-License-Identifier: Apache-2.0
// The skins (lib/skinning/skin.h) on exact axes: accuracy against the ideal tube, no
// blending between folds, closed meshes, warm starts.
#include "skinning/skin.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skinning/convolution_skin.h"
#include "skinning/point_skeleton_skin.h"
#include "skinning/skin_axes.h"
#include "skinning/skin_fixtures.h"
#include "skinning/skin_metrics.h"

namespace {

using namespace skin_test;
using namespace enteron::skinning;
using skin_test::kPi;

const SkinMethod kMethods[] = {SkinMethod::tube, SkinMethod::point_skeleton, SkinMethod::convolution};

const char* skin_name(SkinMethod m) {
    return m == SkinMethod::tube ? "tube" : m == SkinMethod::point_skeleton ? "point_skeleton" : "convolution";
}

TEST(Skins, StraightTubeRadiusErrorBelowHalfAPercentAtDefaultResolution) {
    const auto q = skin_test::straight_axis(41, 0.025);  // 1 m
    for (SkinMethod method : kMethods) {
        auto skin = make_skin(defaults(method));
        const SkinMetrics m = skin_and_measure(*skin, q);
        EXPECT_LT(m.radius_error_rms, 0.005) << skin_name(method);
        EXPECT_TRUE(m.watertight) << skin_name(method);
        EXPECT_EQ(m.blended_vertices, 0u) << skin_name(method);
        EXPECT_EQ(m.inverted_triangles, 0u) << skin_name(method);
        // Volume: the ideal tube plus the rounded ends (4 R / 3 L), less what a 16-gon
        // section misses of the circle (2.5 %) for the ring methods.
        const double section = method == SkinMethod::point_skeleton ? 0.0 : 16 / (2 * kPi) * std::sin(2 * kPi / 16) - 1;
        // Marching-cubes facets of a third of R cut inside the surface by about 2 %.
        EXPECT_NEAR(m.volume_error, 4.0 * R / 3.0 + section, method == SkinMethod::point_skeleton ? 0.03 : 0.005)
            << skin_name(method);
        EXPECT_NEAR(m.axis_length, 1.0, 1e-9);
        for (float u : skin->mesh().u) {
            ASSERT_GE(u, 0.0f);
            ASSERT_LE(u, 1.0f);
        }
    }
}

TEST(Skins, ConvolutionIsoCalibrationGivesRadiusRToAThousandthOfR) {
    for (double window : {0.5 * R, 1.0 * R, 1.9 * R}) {
        SkinSettings s = defaults(SkinMethod::convolution);
        s.window = window;
        ConvolutionSkin skin(s);
        // Closed form for a straight window [-D, D] at distance R: 2 D / (R^2 sqrt(R^2 + D^2)).
        EXPECT_NEAR(skin.iso_value(), 2 * window / (R * R * std::sqrt(R * R + window * window)), 1e-9 * skin.iso_value());
        const auto q = skin_test::straight_axis(21, 0.025);
        const SkinMetrics m = skin_and_measure(skin, q);
        EXPECT_LT(m.radius_error_max, 1e-3) << "window " << window / R << " R";
    }
}

TEST(Skins, TightUTurnNeverBlendsTheLegs) {
    const auto q = skin_test::u_turn_axis(0.15, 2.2 * R, 0.25 * R);
    for (SkinMethod method : {SkinMethod::point_skeleton, SkinMethod::convolution}) {
        auto skin = make_skin(defaults(method));
        const SkinMetrics m = skin_and_measure(*skin, q);
        EXPECT_EQ(m.blended_vertices, 0u) << skin_name(method);
        EXPECT_TRUE(m.watertight) << skin_name(method);
        EXPECT_LT(m.radius_error_rms, 0.05) << skin_name(method);
    }
    // The same document with the window made global (every point sums the whole axis):
    // the metric sees the legs blend. This is what local convolution prevents.
    SkinSettings global = defaults(SkinMethod::convolution);
    global.window = 40 * R;  // longer than the whole axis
    global.skeleton_spacing = R;
    ConvolutionSkin blended(global);
    EXPECT_GT(skin_and_measure(blended, q).blended_vertices, 10u);
}

TEST(Skins, RingsStopShortOfEachOtherAtABendTighterThanR) {
    // Legs 2.2 R apart: the tube is still exact (radius of curvature 1.1 R > R).
    auto tube = make_skin(defaults(SkinMethod::tube));
    const SkinMetrics wide = skin_and_measure(*tube, skin_test::u_turn_axis(0.15, 2.2 * R, 0.25 * R));
    EXPECT_EQ(wide.inverted_triangles, 0u);
    EXPECT_EQ(wide.blended_vertices, 0u);
    EXPECT_LT(wide.radius_error_max, 1e-4);
    // Legs 1.4 R and 1.0 R apart (radius of curvature 0.7 R and 0.5 R): rings of radius R
    // would fold over on the inner side; every ring skin stops its rays short of the
    // neighbouring rings instead (the inner side becomes a crease), at every resolution.
    // The tube's legs still interpenetrate (no contact surfaces), the convolution's meet.
    for (double gap : {1.4, 1.0}) {
        const auto q = skin_test::u_turn_axis(0.15, gap * R, 0.25 * R);
        for (SkinMethod method : {SkinMethod::tube, SkinMethod::convolution}) {
            for (double spacing : {1.0, 0.5, 0.25}) {
                SkinSettings s = defaults(method);
                s.ring_spacing = spacing * R;
                s.segments = spacing < 0.5 ? 32 : spacing > 0.5 ? 8 : 16;
                auto skin = make_skin(s);
                const SkinMetrics m = skin_and_measure(*skin, q);
                EXPECT_EQ(m.inverted_triangles, 0u) << skin_name(method) << " gap " << gap << " R, rings " << spacing << " R";
                EXPECT_TRUE(m.watertight);
                if (method == SkinMethod::tube) {
                    EXPECT_GT(m.blended_vertices, 0u);
                } else {
                    EXPECT_LT(m.overlap_depth_max, 0.01);
                }
            }
        }
    }
}

TEST(Skins, ImplicitMethodsAreWatertightOnBentAndCoiledAxes) {
    const std::vector<double> axes[] = {skin_test::u_turn_axis(0.1, 3.0 * R, 0.5 * R),
                                        skin_test::coil_axis(0.04, 2.6 * R, 3.0, 0.01),
                                        skin_test::coil_axis(0.02, 2.2 * R, 2.0, 0.005)};
    for (SkinMethod method : {SkinMethod::point_skeleton, SkinMethod::convolution}) {
        auto skin = make_skin(defaults(method));
        for (const auto& q : axes) {
            const SkinMetrics m = skin_and_measure(*skin, q);
            EXPECT_TRUE(m.watertight) << skin_name(method) << ": " << m.open_edges << " open, " << m.nonmanifold_edges
                                      << " non-manifold edges";
            EXPECT_GT(m.volume, 0.0) << skin_name(method);  // wound outwards
            EXPECT_EQ(m.blended_vertices, 0u) << skin_name(method);
        }
    }
}

TEST(Skins, PointSkeletonWatertightWhereFoldsTouch) {
    // Two legs of a U-turn about 2 R apart, axis to axis: their surfaces touch or come
    // closer than a voxel, and marching cubes joins them with cells whose faces are
    // ambiguous. Turned and tilted to several angles against the lattice. Each must give a
    // closed, manifold surface (the fan-triangulated table left edges of four triangles
    // here). (Where the surfaces join, vertices lie within 1.1 R of the other leg: the
    // blending count is not zero, by its definition, for folds this close.)
    std::size_t total_triangles = 0;
    for (double gap : {1.95, 2.0, 2.05, 2.1}) {
        for (int turn = 0; turn < 8; ++turn) {
            auto q = skin_test::u_turn_axis(0.1, gap * R, 0.25 * R);
            const double a = 0.3 + 0.17 * turn, b = 0.2 * turn;
            for (std::size_t i = 0; i < q.size(); i += 3) {
                const double x = q[i], y = q[i + 1], z = q[i + 2];
                const double x1 = std::cos(a) * x - std::sin(a) * y, y1 = std::sin(a) * x + std::cos(a) * y;
                q[i] = x1 + 0.001 * turn;
                q[i + 1] = std::cos(b) * y1 - std::sin(b) * z + 0.0007 * turn;
                q[i + 2] = std::sin(b) * y1 + std::cos(b) * z;
            }
            PointSkeletonSkin skin(defaults(SkinMethod::point_skeleton));
            const SkinMetrics m = skin_and_measure(skin, q);
            EXPECT_TRUE(m.watertight) << "gap " << gap << " R, turn " << turn << ": " << m.open_edges << " open, "
                                      << m.nonmanifold_edges << " non-manifold edges";
            EXPECT_GT(m.volume, 0.0);
            total_triangles += m.triangles;
        }
    }
    EXPECT_GT(total_triangles, 32u * 2000u);
}

TEST(Skins, PointSkeletonRadiusDoesNotPulseWhileStretching) {
    // 10 % stretch over 100 frames: the skeleton points follow the length, so the radius
    // error stays within the bound of the unstretched tube on every frame.
    PointSkeletonSkin skin(defaults(SkinMethod::point_skeleton));
    std::size_t first_points = 0, last_points = 0;
    for (int frame = 0; frame <= 100; ++frame) {
        const double stretch = 1.0 + 0.1 * frame / 100.0;
        const auto q = skin_test::straight_axis(21, 0.025 * stretch);
        const SkinMetrics m = skin_and_measure(skin, q);
        ASSERT_LT(m.radius_error_rms, 0.005) << "frame " << frame;
        ASSERT_LT(m.radius_error_max, 0.02) << "frame " << frame;
        ASSERT_TRUE(m.watertight) << "frame " << frame;
        if (frame == 0) first_points = skin.skeleton_points();
        last_points = skin.skeleton_points();
    }
    EXPECT_NEAR(double(last_points) / double(first_points), 1.1, 0.01);
}

TEST(Skins, ConvolutionWarmStartOnAStraightTubeTakesOneEvaluationPerVertex) {
    // On a straight axis every ray's solution is exactly R, so the field there equals the
    // iso-value to the last bit: a solver that then bisected away from its own solution
    // took about three evaluations per vertex warm, more than cold.
    const auto q = skin_test::straight_axis(41, 0.025);
    ConvolutionSkin skin(defaults(SkinMethod::convolution));
    skin.update(q.data(), q.size() / 3);
    skin.update(q.data(), q.size() / 3);
    EXPECT_EQ(skin.last_field_evaluations(), skin.mesh().vertex_count() - 2 - 2 * 4 * 16);
}

TEST(Skins, ConvolutionStartsFromThePreviousFrame) {
    const auto q = skin_test::coil_axis(0.04, 2.6 * R, 2.0, 0.01);
    ConvolutionSkin skin(defaults(SkinMethod::convolution));
    skin.update(q.data(), q.size() / 3);
    const std::size_t cold = skin.last_field_evaluations();
    skin.update(q.data(), q.size() / 3);
    const std::size_t warm = skin.last_field_evaluations();
    // Same axis: each vertex starts on its solution and needs a single evaluation.
    EXPECT_EQ(warm, skin.mesh().vertex_count() - 2 - 2 * 4 * 16);
    EXPECT_LT(warm * 2, cold);
}

TEST(Skins, ConvolutionAdaptiveRingsCutTheFacetErrorOfABendWithFewerTriangles) {
    // Legs 6 R apart: even rings every R leave flat facets on the bend; adaptive rings
    // (at most R apart on the legs, closer on the bend) do better there, with a few more
    // rings than the even R only, far fewer than even rings fine enough for the bend.
    const auto q = skin_test::u_turn_axis(0.3, 6.0 * R, 0.25 * R);
    SkinSettings coarse = defaults(SkinMethod::convolution);
    coarse.ring_spacing = R;
    coarse.segments = 48;
    SkinSettings fine = coarse;
    fine.ring_spacing = 0.25 * R;
    SkinSettings adaptive = coarse;
    adaptive.ring_chord_error = 0.002 * R;
    ConvolutionSkin a(coarse), b(fine), c(adaptive);
    const SkinMetrics even_coarse = skin_and_measure(a, q), even_fine = skin_and_measure(b, q),
                      lod = skin_and_measure(c, q);
    EXPECT_TRUE(lod.watertight);
    EXPECT_EQ(lod.blended_vertices, 0u);
    EXPECT_LT(lod.facet_error_max, 0.8 * even_coarse.facet_error_max);
    EXPECT_LT(lod.triangles, even_fine.triangles / 2);
    EXPECT_LT(lod.radius_error_max, 0.05);
    // Temporal coherence survives the uneven rings: the same axis again starts every
    // body vertex on its solution, one evaluation each.
    c.update(q.data(), q.size() / 3);
    EXPECT_EQ(c.last_field_evaluations(), c.mesh().vertex_count() - 2 - 2 * 4 * 48);
}

TEST(Skins, ConvolutionSkeletonFollowingTheCurvatureIsAsAccurateWithFewerPoints) {
    // A U-turn of radius 1.5 R between straight legs: segment ends R apart on the legs,
    // closer on the bend (chords within 0.002 R of the axis), against even ones R / 4 apart
    // and R apart.
    const auto q = skin_test::u_turn_axis(0.2, 3.0 * R, 0.25 * R);
    SkinSettings fine = defaults(SkinMethod::convolution), coarse = fine, following = fine;
    coarse.skeleton_spacing = R;
    following.skeleton_spacing = R;
    following.skeleton_chord_error = 0.002 * R;
    ConvolutionSkin a(fine), b(coarse), c(following);
    const SkinMetrics even_fine = skin_and_measure(a, q), even_coarse = skin_and_measure(b, q),
                      follows = skin_and_measure(c, q);
    EXPECT_LT(follows.radius_error_max, even_coarse.radius_error_max);
    EXPECT_LT(follows.radius_error_rms, 1.1 * even_fine.radius_error_rms + 1e-4);
    EXPECT_LT(c.skeleton_points(), a.skeleton_points() / 2);
    EXPECT_GT(c.skeleton_points(), b.skeleton_points());
    EXPECT_TRUE(follows.watertight);
    // Warm starts hold on the uneven skeleton: the same axis again, one evaluation a vertex.
    c.update(q.data(), q.size() / 3);
    EXPECT_EQ(c.last_field_evaluations(), c.mesh().vertex_count() - 2 - 2 * 4 * 16);
}

}  // namespace
