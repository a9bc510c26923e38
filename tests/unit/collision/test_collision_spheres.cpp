// SPDX-License-Identifier: Apache-2.0
// The collision spheres (lib/collision/collision_spheres.h): spread evenly by arc length along
// the axis, centred on the spline, their weights and velocities those of the spline.
#include "collision/collision_spheres.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory_resource>
#include <vector>

#include "collision/collision_fixtures.h"
#include "spline/catmull_rom.h"

namespace {

using namespace collision_test;
using enteron::point_at;
using enteron::Vec3;
using enteron::collision::CollisionSpheres;
namespace spline = enteron::spline;

double distance(const Vec3& a, const Vec3& b) { return (a - b).norm(); }

// Control points along a planar spiral-ish curve (curvature varies along it): the point at
// arc parameter u sits on a circle of radius rho(u) = rho0 (1 + 0.5 u / length) swept at a
// rate 1/rho0. `stretch_second_half` spaces the second half of the points `1 + that` times
// farther apart along the curve than the first half, as a locally stretched axis would be.
std::vector<double> curved_points(std::size_t n, double step, double stretch_second_half = 0.0) {
    const double rho0 = 0.08;
    std::vector<double> q;
    double u = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double rho = rho0 * (1.0 + 0.5 * double(i) / double(n));
        const double angle = u / rho0;
        q.insert(q.end(), {rho * std::cos(angle), rho * std::sin(angle), 0.02 * angle});
        u += (i + 1 < n / 2) ? step : step * (1.0 + stretch_second_half);
    }
    return q;
}

// Length of the spline through q (of its first `segments` segments, if given), by a fine
// polyline (far finer than the library's).
double spline_length(const std::vector<double>& q, std::size_t segments = 0) {
    const std::size_t n = q.size() / 3;
    if (segments == 0) segments = n - 1;
    double length = 0.0;
    for (std::size_t s = 0; s < segments; ++s) {
        Vec3 previous = spline::evaluate(q.data(), spline::segment_weights(n, s, 0.0, spline::Derivative::value));
        for (int k = 1; k <= 400; ++k) {
            const Vec3 p = spline::evaluate(q.data(), spline::segment_weights(n, s, k / 400.0, spline::Derivative::value));
            length += distance(p, previous);
            previous = p;
        }
    }
    return length;
}

// Ratio of the largest to the smallest distance between consecutive sphere centres.
double spacing_spread(const CollisionSpheres& spheres, double* mean_spacing = nullptr) {
    double lo = 1e300, hi = 0.0, sum = 0.0;
    for (std::size_t j = 1; j < spheres.size(); ++j) {
        const double d = distance(spheres[j - 1].center, spheres[j].center);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
        sum += d;
    }
    if (mean_spacing != nullptr) *mean_spacing = sum / double(spheres.size() - 1);
    return hi / lo;
}

// Distance from p to the spline, through a polyline of 2000 chords per segment (its own
// chord error is below 1e-9 m here).
double distance_to_spline(const std::vector<double>& q, const Vec3& p) {
    const std::size_t n = q.size() / 3;
    double best = 1e300;
    for (std::size_t s = 0; s + 1 < n; ++s) {
        Vec3 a = spline::evaluate(q.data(), spline::segment_weights(n, s, 0.0, spline::Derivative::value));
        for (int k = 1; k <= 2000; ++k) {
            const Vec3 b = spline::evaluate(q.data(), spline::segment_weights(n, s, k / 2000.0, spline::Derivative::value));
            const Vec3 ab = b - a;
            const double t = std::clamp(ab.dot(p - a) / ab.squaredNorm(), 0.0, 1.0);
            best = std::min(best, distance(a + t * ab, p));
            a = b;
        }
    }
    return best;
}

TEST(CollisionSpheres, CountFollowsTheRestSpacing) {
    const std::vector<double> q = curved_points(30, 0.02);
    CollisionSpheres spheres(30, 0.58, 0.5 * kRadius, kRadius, std::pmr::new_delete_resource());
    // round(0.58 / 0.00625) + 1 = 94 spheres, 0.58 / 93 apart at rest.
    EXPECT_EQ(spheres.size(), 94u);
    EXPECT_NEAR(spheres.rest_spacing(), 0.58 / 93.0, 1e-15);
    EXPECT_EQ(spheres.radius(), kRadius);
}

TEST(CollisionSpheres, EvenlySpacedInArcLengthOnACurvedAxis) {
    const std::size_t n = 30;
    const std::vector<double> q = curved_points(n, 0.02);
    const double length = spline_length(q);
    CollisionSpheres spheres(n, length, 0.5 * kRadius, kRadius, std::pmr::new_delete_resource());
    spheres.update(q.data());
    double mean = 0.0;
    // Chords of arcs of equal length differ by about s^2 / (24 rho^2) ~ 3e-4 here (s = R/2,
    // rho >= 8 cm); 1% leaves room for the polyline the library follows.
    EXPECT_LT(spacing_spread(spheres, &mean), 1.01);
    EXPECT_NEAR(mean * double(spheres.size() - 1), length, 0.01 * length);
    // The ends of the axis carry the first and the last sphere.
    EXPECT_LT(distance(spheres[0].center, point_at(q.data(), 0)), 1e-12);
    EXPECT_LT(distance(spheres[spheres.size() - 1].center, point_at(q.data(), n - 1)), 1e-12);
    // Arc lengths increase evenly from 0 to the length.
    EXPECT_EQ(spheres[0].arc_length, 0.0);
    EXPECT_NEAR(spheres[spheres.size() - 1].arc_length, length, 1e-3 * length);
}

TEST(CollisionSpheres, StillEvenWhenOneHalfOfTheAxisIsStretched) {
    const std::size_t n = 30;
    const std::vector<double> rest = curved_points(n, 0.02);
    const std::vector<double> stretched = curved_points(n, 0.02, 0.2);
    const double rest_length = spline_length(rest);
    CollisionSpheres spheres(n, rest_length, 0.5 * kRadius, kRadius, std::pmr::new_delete_resource());
    spheres.update(stretched.data());
    const std::size_t count = spheres.size();
    // Spacing by spline parameter would show the 20% jump between the two halves.
    double mean = 0.0;
    EXPECT_LT(spacing_spread(spheres, &mean), 1.01);
    // The same spheres spread over the longer axis: about 10% farther apart than at rest.
    const double stretched_length = spline_length(stretched);
    EXPECT_GT(stretched_length, 1.08 * rest_length);
    EXPECT_NEAR(mean, stretched_length / double(count - 1), 0.01 * mean);
    // Each sphere sits at its share of the arc length, not of the parameter: the sphere
    // nearest the middle control point is the one at that point's fraction of the length
    // (the unstretched first half is shorter than the stretched second half).
    const std::size_t middle = n / 2 - 1;
    const double fraction = spline_length(stretched, middle) / stretched_length;
    ASSERT_LT(fraction, 0.47);
    std::size_t nearest = 0;
    double best = 1e300;
    for (std::size_t j = 0; j < count; ++j) {
        const double d = distance(spheres[j].center, point_at(stretched.data(), middle));
        if (d < best) best = d, nearest = j;
    }
    EXPECT_NEAR(double(nearest), fraction * double(count - 1), 1.0);
    EXPECT_LT(best, 0.6 * mean);
}

TEST(CollisionSpheres, CentresLieOnTheSpline) {
    const std::size_t n = 30;
    const std::vector<double> q = curved_points(n, 0.02, 0.2);
    CollisionSpheres spheres(n, spline_length(q), 0.5 * kRadius, kRadius, std::pmr::new_delete_resource());
    spheres.update(q.data());
    // A centre on a chord between spline points dt apart in the segment parameter lies within
    // dt^2 / 8 max|P''| of the spline (linear interpolation error). The library follows the
    // spline at no coarser than a quarter segment: dt <= 1/4.
    double max_second = 0.0;
    for (std::size_t s = 0; s + 1 < n; ++s)
        for (double t : {0.0, 1.0}) {  // P'' is linear in t: largest at an end
            const Vec3 second = spline::evaluate(q.data(), spline::segment_weights(n, s, t, spline::Derivative::second));
            max_second = std::max(max_second, second.norm());
        }
    const double bound = max_second / (16.0 * 8.0);
    ASSERT_LT(bound, 0.02 * kRadius) << "the test curve should be smooth";
    ASSERT_GT(bound, 1e-6) << "the test curve should be curved enough to tell";
    double worst = 0.0;
    for (std::size_t j = 0; j < spheres.size(); ++j) {
        worst = std::max(worst, distance_to_spline(q, spheres[j].center));
        // The weights that carry the sphere's force give back its centre.
        EXPECT_LT(distance(spline::evaluate(q.data(), spheres[j].weights), spheres[j].center), 1e-12) << "sphere " << j;
        double weight_sum = 0.0;
        for (double w : spheres[j].weights.w) weight_sum += w;
        EXPECT_NEAR(weight_sum, 1.0, 1e-12) << "sphere " << j;
    }
    EXPECT_LT(worst, bound + 1e-9);
}

TEST(CollisionSpheres, VelocitiesFollowTheVelocitiesAndThePlacement) {
    // Cached per placement and velocities: a new v at the same q, and a new q with the same
    // v, must both give the centres' velocities anew.
    const std::size_t n = 30;
    std::vector<double> q = curved_points(n, 0.02, 0.2);
    CollisionSpheres spheres(n, spline_length(q), 0.5 * kRadius, kRadius, std::pmr::new_delete_resource());
    std::vector<double> v(3 * n);
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = std::sin(0.7 * double(k));
    auto expect_velocities = [&](const char* when) {
        const double* got = spheres.velocities(v.data());
        for (std::size_t j = 0; j < spheres.size(); ++j) {
            const Vec3 expected = spline::evaluate(v.data(), spheres[j].weights);
            for (int c = 0; c < 3; ++c) ASSERT_EQ(got[3 * j + c], expected[c]) << when << ", sphere " << j;
        }
    };
    spheres.update(q.data());
    expect_velocities("first");
    for (double& x : v) x *= -0.5;
    expect_velocities("new v, same q");
    for (std::size_t k = 0; k < q.size(); k += 3) q[k] *= 1.1;  // stretched along x
    spheres.update(q.data());
    expect_velocities("same v, new q");
}

}  // namespace

namespace {

// With a radius profile, each sphere takes the radius at its place and the spacing follows
// it: neighbours are spacing x R(s) / R_max apart at rest, the same fraction of their radius
// everywhere (to first order in the change of R over one spacing).
TEST(CollisionSpheres, ARadiusProfileSetsEachSphereAndItsSpacing) {
    const enteron::spline::LengthProfile profile({0.0, 0.035, 1.5, 0.013}, std::pmr::new_delete_resource());
    const std::size_t n = 61;
    const std::vector<double> q = straight(n, 1.5 / double(n - 1));
    CollisionSpheres spheres(n, 1.5, 0.5 * 0.035, 0.035, std::pmr::new_delete_resource(), {}, &profile);
    spheres.update(q.data());
    EXPECT_EQ(spheres.radius(), 0.035);
    // The count: R_max x integral of ds / R(s), in steps of the spacing; more than the
    // 1.5 / 0.0175 + 1 = 87 spheres of the largest radius everywhere.
    const double span = 0.035 * 1.5 * std::log(0.013 / 0.035) / (0.013 - 0.035);
    EXPECT_EQ(spheres.size(), static_cast<std::size_t>(std::llround(span / 0.0175)) + 1);
    EXPECT_GT(spheres.size(), 87u);
    EXPECT_NEAR(spheres[0].center.x(), 0.0, 1e-12);
    EXPECT_NEAR(spheres[spheres.size() - 1].center.x(), 1.5, 1e-12);
    for (std::size_t j = 0; j < spheres.size(); ++j) {
        const double s = spheres[j].center.x();  // a straight axis at rest: x is the arc length
        EXPECT_NEAR(spheres[j].radius, profile.at(s), 1e-12) << j;
        if (j == 0) continue;
        const double gap = s - spheres[j - 1].center.x();
        const double middle_radius = profile.at(s - 0.5 * gap);
        EXPECT_NEAR(gap / middle_radius, spheres.rest_spacing() / 0.035, 1e-3) << j;
    }
}

// Two tubes in one state (mechanics/axis_model.h): each tube's spheres are those of the
// tube alone, after the first tube's, with weights on its own points and its tube index.
TEST(CollisionSpheres, TheSpheresOfTwoTubesAreEachTubesAlone) {
    const std::vector<double> a = curved_points(11, 0.02), b = curved_points(8, 0.015, 0.3);
    std::vector<double> both = a;
    both.insert(both.end(), b.begin(), b.end());
    const spline::Ends clamped_first{spline::EndTreatment::quadratic, spline::EndTreatment::linear};
    CollisionSpheres alone_a(11, 0.2, 0.006, kRadius, std::pmr::new_delete_resource());
    CollisionSpheres alone_b(8, 0.105, 0.004, 0.02, std::pmr::new_delete_resource(), clamped_first);
    CollisionSpheres together({{0, 11, 0.2, 0.006, kRadius, {}, nullptr}, {11, 8, 0.105, 0.004, 0.02, clamped_first, nullptr}},
                              19, std::pmr::new_delete_resource());
    alone_a.update(a.data());
    alone_b.update(b.data());
    together.update(both.data());
    ASSERT_EQ(together.tube_count(), 2u);
    ASSERT_EQ(together.size(), alone_a.size() + alone_b.size());
    EXPECT_EQ(together.tube_begin(1), alone_a.size());
    EXPECT_EQ(together.radius(), 0.02);  // the largest of every tube
    EXPECT_EQ(together.tube_rest_spacing(1), alone_b.rest_spacing());
    for (std::size_t j = 0; j < together.size(); ++j) {
        const bool second = j >= alone_a.size();
        const enteron::collision::Sphere& alone = second ? alone_b[j - alone_a.size()] : alone_a[j];
        const enteron::collision::Sphere& sphere = together[j];
        EXPECT_EQ(sphere.tube, second ? 1u : 0u) << j;
        EXPECT_EQ(sphere.center, alone.center) << j;
        EXPECT_EQ(sphere.radius, alone.radius) << j;
        EXPECT_EQ(sphere.weights.first, alone.weights.first + (second ? 11u : 0u)) << j;
        EXPECT_EQ(sphere.weights.w, alone.weights.w) << j;
    }
}

}  // namespace
