// SPDX-License-Identifier: Apache-2.0
// The skins with a radius profile (skinning/tube_radius.h): a tube tapering from 3.5 to
// 1.3 cm (a colon's caecum to its sigmoid) drawn by every method at the profile's radius
// at each place, within the bounds the constant tube keeps (test_skin.cpp), checked both
// by the metrics and independently of them; a flat profile draws the constant tube.
#include "skinning/tube_radius.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "skinning/skin.h"
#include "skinning/skin_axes.h"
#include "skinning/skin_fixtures.h"
#include "skinning/skin_metrics.h"

namespace {

using namespace enteron::skinning;

constexpr double kTaperWide = 0.035, kTaperThin = 0.013, kTaperLength = 1.5;
constexpr int kTaperPoints = 61;  // l0 = 2.5 cm

const SkinMethod kTaperMethods[] = {SkinMethod::tube, SkinMethod::point_skeleton, SkinMethod::convolution};

const char* taper_method_name(SkinMethod m) {
    return m == SkinMethod::tube ? "tube" : m == SkinMethod::point_skeleton ? "point_skeleton" : "convolution";
}

double taper_radius(double s) {
    return kTaperWide + (kTaperThin - kTaperWide) * std::clamp(s / kTaperLength, 0.0, 1.0);
}

TubeRadius taper_along(double wide, double thin) {
    TubeRadius along;
    along.profile = std::make_shared<const enteron::spline::LengthProfile>(
        std::vector<double>{0.0, wide, kTaperLength, thin}, std::pmr::get_default_resource());
    along.segment_rest_length = kTaperLength / (kTaperPoints - 1);
    return along;
}

// The defaults of ent_skin_desc_default scaled by the largest radius, as the C API makes them.
SkinSettings taper_settings(SkinMethod method, const TubeRadius& along) {
    SkinSettings s;
    const double R = kTaperWide;
    s.method = method;
    s.radius = R;
    s.ring_spacing = 0.5 * R;
    s.skeleton_spacing = 0.25 * R;
    s.voxel_size = R / 3.0;
    s.window = R;
    s.radius_along = along;
    return s;
}

SkinMetrics taper_measure(const Skin& skin, const TubeRadius& along) {
    return measure_skin(skin.mesh(), skin.axis_points(), skin.axis_count(), skin.arc_length(), kTaperWide, along);
}

TEST(TubeRadius, ATaperedStraightTubeIsDrawnAtTheProfilesRadiusByEveryMethod) {
    const auto q = skin_test::straight_axis(kTaperPoints, kTaperLength / (kTaperPoints - 1));
    const TubeRadius along = taper_along(kTaperWide, kTaperThin);
    for (SkinMethod method : kTaperMethods) {
        auto skin = make_skin(taper_settings(method, along));
        skin->update(q.data(), q.size() / 3);
        const SkinMetrics m = taper_measure(*skin, along);
        // The constant tube's bounds (test_skin.cpp: RMS under half a percent on a straight
        // axis, at most 2 % anywhere), each vertex against the radius at its own place.
        EXPECT_LT(m.radius_error_rms, 0.005) << taper_method_name(method);
        EXPECT_LT(m.radius_error_max, 0.02) << taper_method_name(method);
        EXPECT_TRUE(m.watertight) << taper_method_name(method);
        EXPECT_EQ(m.inverted_triangles, 0u) << taper_method_name(method);
        // The volume against pi int r^2 ds = pi L (a^2 + a b + b^2) / 3: the two half-sphere
        // ends add 2 pi (a^3 + b^3) / 3; a 16-gon misses its share of the circle for the
        // ring methods. The point skeleton's marching-cubes facets cut inside the surface,
        // about 2 % at a voxel of R / 3, more where the tube is thinner than the voxel's R.
        const double a = kTaperWide, b = kTaperThin;
        const double ends = 2.0 * (a * a * a + b * b * b) / (kTaperLength * (a * a + a * b + b * b));
        if (method == SkinMethod::point_skeleton) {
            EXPECT_LT(m.volume_error, ends - 0.01);
            EXPECT_GT(m.volume_error, ends - 0.05);
        } else {
            const double section = 16 / (2 * skin_test::kPi) * std::sin(2 * skin_test::kPi / 16) - 1;
            EXPECT_NEAR(m.volume_error, ends + section, 0.005) << taper_method_name(method);
        }
        // Independently of the metrics: the axis is the x axis from 0, so a body vertex at x
        // lies at arc length x and must be r(x) from the axis.
        double worst = 0.0;
        const std::vector<float>& p = skin->mesh().positions;
        for (std::size_t i = 0; i + 2 < p.size(); i += 3) {
            const double x = p[i];
            if (x < 0.1 || x > kTaperLength - 0.1) continue;  // the caps, and their ring
            const double r = std::hypot(double(p[i + 1]), double(p[i + 2]));
            worst = std::max(worst, std::fabs(r - taper_radius(x)) / taper_radius(x));
        }
        EXPECT_LT(worst, 0.02) << taper_method_name(method);
        // Against the largest radius everywhere the same mesh is far off: the test can tell.
        const SkinMetrics constant = measure_skin(skin->mesh(), skin->axis_points(), skin->axis_count(),
                                                  skin->arc_length(), kTaperWide);
        EXPECT_GT(constant.radius_error_rms, 0.2) << taper_method_name(method);
        std::printf("[ taper ] %-14s radius error RMS %.3f %% max %.3f %%, off the axis by r(x) at worst %.3f %%, "
                    "facet error RMS %.2f %% max %.2f %%, volume error %.2f %%\n",
                    taper_method_name(method), 100 * m.radius_error_rms, 100 * m.radius_error_max, 100 * worst,
                    100 * m.facet_error_rms, 100 * m.facet_error_max, 100 * m.volume_error);
    }
}

TEST(TubeRadius, ATaperedCoilIsDrawnAtTheProfilesRadiusAwayFromBends) {
    // A coil of radius 12 cm (over 3 of the largest radii), 10 cm of rise per turn: its turns
    // do not touch; every vertex bends with a radius above R, so all are free.
    auto q = skin_test::coil_axis(0.12, 0.10, 2.0, 0.025);
    const std::size_t count = q.size() / 3;
    TubeRadius along = taper_along(kTaperWide, kTaperThin);
    along.segment_rest_length = kTaperLength / double(count - 1);  // the profile over the coil's length
    for (SkinMethod method : kTaperMethods) {
        auto skin = make_skin(taper_settings(method, along));
        skin->update(q.data(), count);
        const SkinMetrics m = taper_measure(*skin, along);
        EXPECT_LT(m.free_radius_error_rms, 0.01) << taper_method_name(method);
        EXPECT_LT(m.radius_error_rms, 0.01) << taper_method_name(method);
        EXPECT_EQ(m.blended_vertices, 0u) << taper_method_name(method);
        std::printf("[ taper coil ] %-14s radius error RMS %.3f %% max %.3f %%, free RMS %.3f %% (%zu free)\n",
                    taper_method_name(method), 100 * m.radius_error_rms, 100 * m.radius_error_max,
                    100 * m.free_radius_error_rms, m.free_vertices);
    }
}

TEST(TubeRadius, AFlatProfileDrawsTheConstantTube) {
    // The profile's code path with r = R everywhere: the same mesh as no profile, to round-off.
    const auto q = skin_test::coil_axis(0.12, 0.10, 1.0, 0.025);
    const TubeRadius flat = taper_along(kTaperWide, kTaperWide);
    for (SkinMethod method : kTaperMethods) {
        auto constant = make_skin(taper_settings(method, TubeRadius{}));
        auto profiled = make_skin(taper_settings(method, flat));
        constant->update(q.data(), q.size() / 3);
        profiled->update(q.data(), q.size() / 3);
        const std::vector<float>& a = constant->mesh().positions;
        const std::vector<float>& b = profiled->mesh().positions;
        ASSERT_EQ(a.size(), b.size()) << taper_method_name(method);
        double worst = 0.0;
        for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::fabs(double(a[i]) - double(b[i])));
        EXPECT_LT(worst, 1e-6 * kTaperWide) << taper_method_name(method);
    }
}

}  // namespace
