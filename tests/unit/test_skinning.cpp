// The skins of lib/skinning on exact axes: accuracy against the ideal tube, no blending
// between folds, closed meshes, rotation-minimising frames, the marching cubes table and
// the exporters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <sstream>
#include <string>

#include "skin_axes.h"
#include "skinning/convolution_skin.h"
#include "skinning/marching_cubes.h"
#include "skinning/marching_cubes_table.h"
#include "skinning/mesh_writers.h"
#include "skinning/point_skeleton_skin.h"
#include "skinning/ring_placement.h"
#include "skinning/rotation_minimizing_frames.h"
#include "skinning/skin.h"
#include "skinning/skin_metrics.h"
#include "skinning/segment_kernel.h"

namespace {

using namespace enteron::skinning;
using enteron::normalized_or;
using enteron::Vec3;
using skin_test::kPi;

constexpr double R = 0.0125;

// The defaults of ent_skin_desc_default, in metres.
SkinSettings defaults(SkinMethod method) {
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

SkinMetrics skin_and_measure(Skin& skin, const std::vector<double>& q) {
    skin.update(q.data(), q.size() / 3);
    return measure_skin(skin.mesh(), skin.axis_points(), skin.axis_count(), skin.arc_length(), R);
}

// Random field values in [-1, 1] at the corners of `block`, every corner in the band, and
// -1 (outside) on the outer layer of the lattice of `extent` corners per side that the
// block belongs to, so that the surface closes.
void fill_random(VoxelBlock& block, std::mt19937& random, int extent) {
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    for (int z = 0; z < kBlockSize; ++z)
        for (int y = 0; y < kBlockSize; ++y)
            for (int x = 0; x < kBlockSize; ++x) {
                const int g[3] = {block.coordinates[0] * kBlockSize + x, block.coordinates[1] * kBlockSize + y,
                                  block.coordinates[2] * kBlockSize + z};
                bool border = false;
                for (int c : g) border = border || c == 0 || c == extent - 1;
                const std::size_t i = SparseVoxelGrid::local_index(x, y, z);
                block.nearest[i] = nearest_key(0.0f, 0);
                block.field[i] = border ? -1.0f : value(random);
            }
}

// Every directed edge appears once and its reverse once: closed, manifold and
// consistently wound.
void expect_closed_and_consistently_wound(const Mesh& mesh) {
    std::vector<std::pair<uint32_t, uint32_t>> directed;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
        for (int e = 0; e < 3; ++e) directed.emplace_back(mesh.indices[3 * t + e], mesh.indices[3 * t + (e + 1) % 3]);
    std::sort(directed.begin(), directed.end());
    std::size_t failures = 0;
    for (std::size_t i = 0; i < directed.size() && failures < 10; ++i) {
        const auto [a, b] = directed[i];
        const bool once = (i == 0 || directed[i - 1] != directed[i]) &&
                          (i + 1 == directed.size() || directed[i + 1] != directed[i]);
        const bool reverse = std::binary_search(directed.begin(), directed.end(), std::make_pair(b, a));
        EXPECT_TRUE(once && reverse) << "edge " << a << " -> " << b;
        if (!(once && reverse)) ++failures;
    }
}

const SkinMethod kMethods[] = {SkinMethod::tube, SkinMethod::point_skeleton, SkinMethod::convolution};
const char* name(SkinMethod m) {
    return m == SkinMethod::tube ? "tube" : m == SkinMethod::point_skeleton ? "point_skeleton" : "convolution";
}

TEST(SegmentKernel, MatchesNumericalIntegralOf1OverR3) {
    const Vec3 a{0.1, -0.2, 0.05}, b{0.4, 0.3, -0.1}, p{0.2, 0.35, 0.3};
    const int n = 200000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) / n;
        const Vec3 x = a + t * (b - a);
        const double r = (p - x).norm();
        sum += (b - a).norm() / n / (r * r * r);
    }
    EXPECT_NEAR(segment_field(p, a, b), sum, 1e-8 * sum);
    // Additive: two halves make the whole.
    const Vec3 m = 0.5 * (a + b);
    EXPECT_NEAR(segment_field(p, a, m) + segment_field(p, m, b), segment_field(p, a, b), 1e-12 * sum);
}

TEST(RotationMinimizingFrames, StayOrthonormalAndDoNotTwistOnAPlanarCurve) {
    // A planar curve: the rotation-minimising normal that starts in the plane's normal
    // direction stays exactly there (no twist), whatever the bending.
    std::vector<Vec3> x, t;
    for (int i = 0; i <= 400; ++i) {
        const double a = 3.0 * std::sin(i * 0.03);
        x.push_back({std::cos(a) + 0.01 * i, std::sin(a), 0.0});
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
        const Vec3 d = x[std::min(i + 1, x.size() - 1)] - x[i == 0 ? 0 : i - 1];
        t.push_back(normalized_or(d, Vec3{1, 0, 0}));
    }
    RotationMinimizingFrames frames;
    frames.build(x.data(), t.data(), x.size());
    // The first normal is arbitrary; rotate the test to its plane component.
    const double z0 = frames.normal(0).z();
    for (std::size_t i = 0; i < x.size(); ++i) {
        EXPECT_NEAR(frames.normal(i).dot(t[i]), 0.0, 1e-12);
        EXPECT_NEAR(frames.normal(i).norm(), 1.0, 1e-12);
        EXPECT_NEAR(frames.normal(i).z(), z0, 1e-9) << "twist at sample " << i;
    }
}

TEST(MarchingCubesTable, EverySingleCornerCaseFacesAwayFromTheInsideCorner) {
    const auto& table = marching_cubes_table();
    for (int c = 0; c < 8; ++c) {
        const MarchingCubesCase& entry = table[std::size_t(1 << c)];
        ASSERT_EQ(entry.triangle_count, 1);
        Vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            const auto& e = kEdgeCorners[entry.edges[std::size_t(k)]];
            const Vec3 a{double(e[0] & 1), double((e[0] >> 1) & 1), double((e[0] >> 2) & 1)};
            const Vec3 b{double(e[1] & 1), double((e[1] >> 1) & 1), double((e[1] >> 2) & 1)};
            p[k] = 0.5 * (a + b);
        }
        const Vec3 corner{double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)};
        EXPECT_LT((p[1] - p[0]).cross(p[2] - p[0]).dot(corner - p[0]), 0.0) << "case " << (1 << c);
    }
    // Complementary cases have the same number of crossing edges.
    for (int mask = 0; mask < 256; ++mask)
        EXPECT_EQ(table[std::size_t(mask)].triangle_count == 0, mask == 0 || mask == 255) << mask;
}

TEST(MarchingCubes, RandomFieldGivesAClosedConsistentlyWoundSurface) {
    // Random signs on a small lattice exercise every ambiguous face; the band covers the
    // lattice and its outer layer is outside, so the surface must close.
    std::mt19937 random(7);
    SparseVoxelGrid grid;
    grid.reset(1.0, 8);
    fill_random(grid.block(grid.touch(0, 0, 0)), random, kBlockSize);
    Mesh mesh;
    std::vector<int32_t> seeds;
    MarchingCubes cubes;
    cubes.extract(grid, 0.0, mesh, seeds);
    ASSERT_GT(mesh.triangle_count(), 100u);
    expect_closed_and_consistently_wound(mesh);
}

TEST(MarchingCubesTable, NoTriangleEdgeJoinsTwoVerticesOfAFaceThatTheFaceLeavesApart) {
    // A triangle edge inside a cell whose two vertices lie on one face of the cell, without
    // a face segment between them, crosses that face; the cell on the other side sees the
    // same two vertices, apart, on the same face and may draw the same edge: it would then
    // belong to four triangles (a non-manifold edge: the fan triangulation did this in 18
    // cases, where two folds touch).
    const auto& table = marching_cubes_table();
    auto on_face = [](int e, int axis, int side) {
        return ((kEdgeCorners[std::size_t(e)][0] >> axis) & 1) == side && ((kEdgeCorners[std::size_t(e)][1] >> axis) & 1) == side;
    };
    for (int mask = 0; mask < 256; ++mask) {
        const MarchingCubesCase& entry = table[std::size_t(mask)];
        std::map<std::pair<int, int>, int> uses;  // triangle edges of the case
        for (int t = 0; t < entry.triangle_count; ++t)
            for (int k = 0; k < 3; ++k) {
                const int a = entry.edges[std::size_t(3 * t + k)], b = entry.edges[std::size_t(3 * t + (k + 1) % 3)];
                ++uses[{std::min(a, b), std::max(a, b)}];
            }
        for (const auto& [edge, count] : uses) {
            if (count == 1) continue;  // on the loop: a face segment (or the cell's own edge)
            for (int axis = 0; axis < 3; ++axis)
                for (int side = 0; side < 2; ++side)
                    EXPECT_FALSE(on_face(edge.first, axis, side) && on_face(edge.second, axis, side))
                        << "case " << mask << ": diagonal between edges " << edge.first << " and " << edge.second;
        }
    }
}

TEST(MarchingCubes, RandomFieldsAcrossBlocksGiveClosedManifoldSurfaces) {
    // Random signs on 2 x 2 x 2 blocks (cells across block boundaries too), an outside
    // layer all round; many seeds, so that two neighbouring cells often share an ambiguous
    // face. Fails with the fan-triangulated table (edges of four triangles).
    for (unsigned seed = 1; seed <= 20; ++seed) {
        std::mt19937 random(seed);
        SparseVoxelGrid grid;
        grid.reset(1.0, 8);
        for (int b = 0; b < 8; ++b) fill_random(grid.block(grid.touch(b & 1, (b >> 1) & 1, b >> 2)), random, 2 * kBlockSize);
        Mesh mesh;
        std::vector<int32_t> seeds;
        MarchingCubes cubes;
        cubes.extract(grid, 0.0, mesh, seeds);
        ASSERT_GT(mesh.triangle_count(), 1000u);
        SCOPED_TRACE("seed " + std::to_string(seed));
        expect_closed_and_consistently_wound(mesh);
    }
}

TEST(Skins, StraightTubeRadiusErrorBelowHalfAPercentAtDefaultResolution) {
    const auto q = skin_test::straight_axis(41, 0.025);  // 1 m
    for (SkinMethod method : kMethods) {
        auto skin = make_skin(defaults(method));
        const SkinMetrics m = skin_and_measure(*skin, q);
        EXPECT_LT(m.radius_error_rms, 0.005) << name(method);
        EXPECT_TRUE(m.watertight) << name(method);
        EXPECT_EQ(m.blended_vertices, 0u) << name(method);
        EXPECT_EQ(m.inverted_triangles, 0u) << name(method);
        // Volume: the ideal tube plus the rounded ends (4 R / 3 L), less what a 16-gon
        // section misses of the circle (2.5 %) for the ring methods.
        const double section = method == SkinMethod::point_skeleton ? 0.0 : 16 / (2 * kPi) * std::sin(2 * kPi / 16) - 1;
        // Marching-cubes facets of a third of R cut inside the surface by about 2 %.
        EXPECT_NEAR(m.volume_error, 4.0 * R / 3.0 + section, method == SkinMethod::point_skeleton ? 0.03 : 0.005)
            << name(method);
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
        EXPECT_EQ(m.blended_vertices, 0u) << name(method);
        EXPECT_TRUE(m.watertight) << name(method);
        EXPECT_LT(m.radius_error_rms, 0.05) << name(method);
    }
    // The same document with the window made global (every point sums the whole axis):
    // the metric sees the legs blend. This is what local convolution prevents.
    SkinSettings global = defaults(SkinMethod::convolution);
    global.window = 40 * R;  // longer than the whole axis
    global.skeleton_spacing = R;
    ConvolutionSkin blended(global);
    EXPECT_GT(skin_and_measure(blended, q).blended_vertices, 10u);
}

TEST(Skins, TubeArtefactAtABendTighterThanR) {
    // Legs 2.2 R apart: the tube is still exact (radius of curvature 1.1 R > R).
    auto tube = make_skin(defaults(SkinMethod::tube));
    const SkinMetrics wide = skin_and_measure(*tube, skin_test::u_turn_axis(0.15, 2.2 * R, 0.25 * R));
    EXPECT_EQ(wide.inverted_triangles, 0u);
    EXPECT_EQ(wide.blended_vertices, 0u);
    // Legs 1.4 R apart (radius of curvature 0.7 R): the inner side of the rings folds over
    // and the legs interpenetrate: inverted triangles and vertices inside the other leg.
    const SkinMetrics tight = skin_and_measure(*tube, skin_test::u_turn_axis(0.15, 1.4 * R, 0.25 * R));
    EXPECT_GT(tight.inverted_triangles, 0u);
    EXPECT_GT(tight.blended_vertices, 0u);
}

TEST(Skins, ImplicitMethodsAreWatertightOnBentAndCoiledAxes) {
    const std::vector<double> axes[] = {skin_test::u_turn_axis(0.1, 3.0 * R, 0.5 * R),
                                        skin_test::coil_axis(0.04, 2.6 * R, 3.0, 0.01),
                                        skin_test::coil_axis(0.02, 2.2 * R, 2.0, 0.005)};
    for (SkinMethod method : {SkinMethod::point_skeleton, SkinMethod::convolution}) {
        auto skin = make_skin(defaults(method));
        for (const auto& q : axes) {
            const SkinMetrics m = skin_and_measure(*skin, q);
            EXPECT_TRUE(m.watertight) << name(method) << ": " << m.open_edges << " open, " << m.nonmanifold_edges
                                      << " non-manifold edges";
            EXPECT_GT(m.volume, 0.0) << name(method);  // wound outwards
            EXPECT_EQ(m.blended_vertices, 0u) << name(method);
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

TEST(RingPlacement, RingsComeCloserOnABendByTheChordErrorBound) {
    // A U-turn of radius rho = 3 R between straight legs: on the half circle the spacing is
    // sqrt(8 e / (k (1 + k R))) with k = 1 / rho; on the legs, away from the bend, the
    // largest spacing.
    const double rho = 3.0 * R, e = 0.01 * R, largest = 2.0 * R;
    const auto q = skin_test::u_turn_axis(0.2, 2.0 * rho, 0.25 * R);
    SkinSettings s = defaults(SkinMethod::convolution);
    auto skin = make_skin(s);  // for its arc-length table
    skin->update(q.data(), q.size() / 3);
    AxisSamples axis;
    axis.build(skin->arc_length(), skin->axis_points(), skin->axis_count(), 0.25 * R, 0.0);
    RingPlacement placement;
    const std::vector<double>& rings = placement.place(axis, R, largest, 0.05 * R, e);
    const double k = 1.0 / rho, bend = std::sqrt(8.0 * e / (k * (1.0 + k * R)));
    const double leg = 0.2, arc = kPi * rho;  // the half circle spans [leg, leg + arc] in arc length
    ASSERT_NEAR(rings.back(), 2 * leg + arc, 1e-3);
    EXPECT_EQ(rings.front(), 0.0);
    std::size_t on_bend = 0;
    for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
        const double a = rings[i], b = rings[i + 1], gap = b - a;
        ASSERT_GT(gap, 0.0);
        EXPECT_LE(gap, largest * 1.001);
        if (a > leg + 0.1 * arc && b < leg + 0.9 * arc) {  // well inside the bend
            EXPECT_NEAR(gap, bend, 0.1 * bend) << "at " << a;
            ++on_bend;
        }
        if (b < leg - 2 * largest || a > leg + arc + 2 * largest) {
            EXPECT_GT(gap, 0.9 * largest) << "at " << a;
        }
    }
    EXPECT_GT(on_bend, 10u);
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

TEST(MeshWriters, ObjAndPlyDescribeTheMesh) {
    auto skin = make_skin(defaults(SkinMethod::tube));
    const auto q = skin_test::straight_axis(5, 0.025);
    skin->update(q.data(), q.size() / 3);
    const Mesh& mesh = skin->mesh();

    std::ostringstream obj;
    ASSERT_TRUE(write_obj(mesh, obj));
    std::istringstream lines(obj.str());
    std::string line;
    std::size_t v = 0, f = 0;
    double last_x = 0.0;
    while (std::getline(lines, line)) {
        if (line.rfind("v ", 0) == 0) {
            ++v;
            last_x = std::stod(line.substr(2));
        }
        if (line.rfind("f ", 0) == 0) ++f;
    }
    EXPECT_EQ(v, mesh.vertex_count());
    EXPECT_EQ(f, mesh.triangle_count());
    EXPECT_FLOAT_EQ(float(last_x), mesh.positions[3 * (mesh.vertex_count() - 1)]);

    std::ostringstream ply;
    ASSERT_TRUE(write_ply(mesh, ply));
    const std::string text = ply.str();
    const std::size_t header = text.find("end_header\n") + std::strlen("end_header\n");
    EXPECT_NE(text.find("element vertex " + std::to_string(mesh.vertex_count())), std::string::npos);
    EXPECT_EQ(text.size() - header, mesh.vertex_count() * 7 * 4 + mesh.triangle_count() * (1 + 3 * 4));
    float x0;
    std::memcpy(&x0, text.data() + header, 4);
    EXPECT_EQ(x0, mesh.positions[0]);
}

}  // namespace
