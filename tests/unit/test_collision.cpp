// Collision geometry and the contact law (lib/collision/): spheres spread evenly by arc
// length along the axis, the contacts each obstacle reports, the penalty contact force and
// the environment effect that maps it to the control points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory_resource>
#include <vector>

#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/environment_force.h"
#include "collision/obstacle.h"
#include "collision/sphere_loads.h"
#include "mechanics/state.h"
#include "spline/catmull_rom.h"

namespace {

using enteron::point_at;
using enteron::Vec3;
using enteron::collision::CollisionSpheres;
using enteron::collision::contact_force;
using enteron::collision::ContactForce;
using enteron::collision::ContactParameters;
using enteron::collision::EnvironmentForce;
using enteron::collision::for_each_contact;
using enteron::collision::Obstacle;
using enteron::collision::ObstacleContact;
using enteron::collision::ObstacleKind;
using enteron::collision::SphereLoads;
using enteron::mechanics::AxisModel;
using enteron::mechanics::ContactSummary;
using enteron::mechanics::State;
namespace spline = enteron::spline;

using enteron::kPi;
constexpr double kRadius = 0.0125;

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

// ---- collision spheres ---------------------------------------------------------------

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

// ---- obstacles -------------------------------------------------------------------------

std::vector<ObstacleContact> contacts_of(const Obstacle& o, const Vec3& p, double r) {
    std::vector<ObstacleContact> out;
    for_each_contact(o, p, r, [&](const ObstacleContact& c) { out.push_back(c); });
    return out;
}

void expect_normal(const ObstacleContact& c, double x, double y, double z, double tolerance = 1e-12) {
    EXPECT_NEAR(c.normal[0], x, tolerance);
    EXPECT_NEAR(c.normal[1], y, tolerance);
    EXPECT_NEAR(c.normal[2], z, tolerance);
}

Obstacle box(double cx, double cy, double cz, double hx, double hy, double hz) {
    Obstacle o;
    o.kind = ObstacleKind::box_inside;
    o.center = {cx, cy, cz};
    o.extent = {hx, hy, hz};
    return o;
}

TEST(Obstacle, BoxInsideWallsAndCorner) {
    const Obstacle o = box(1.0, 2.0, 3.0, 0.1, 0.2, 0.3);
    const double r = 0.01;
    // Well inside: nothing. Touching a wall exactly: nothing (depth 0).
    const Vec3 inside(1.0, 2.0, 3.0);
    EXPECT_TRUE(contacts_of(o, inside, r).empty());
    const Vec3 touching(1.09, 2.0, 3.0);
    EXPECT_TRUE(contacts_of(o, touching, r).empty());
    // One wall, the low z one: the sphere reaches 0.004 below the floor.
    const Vec3 floor(1.0, 2.0, 3.0 - 0.3 + 0.006);
    auto c = contacts_of(o, floor, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.004, 1e-12);
    expect_normal(c[0], 0, 0, 1);
    // A centre beyond the wall is deeper than R, pushed back the same way.
    const Vec3 beyond(1.0 - 0.1 - 0.002, 2.0, 3.0);
    c = contacts_of(o, beyond, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.012, 1e-12);
    expect_normal(c[0], 1, 0, 0);
    // A corner (high x, low y, high z): three contacts, one per wall, each with its depth.
    const Vec3 corner(1.0 + 0.096, 2.0 - 0.197, 3.0 + 0.292);
    c = contacts_of(o, corner, r);
    ASSERT_EQ(c.size(), 3u);
    std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.depth < b.depth; });
    EXPECT_NEAR(c[0].depth, 0.002, 1e-12);
    expect_normal(c[0], 0, 0, -1);
    EXPECT_NEAR(c[1].depth, 0.006, 1e-12);
    expect_normal(c[1], -1, 0, 0);
    EXPECT_NEAR(c[2].depth, 0.007, 1e-12);
    expect_normal(c[2], 0, 1, 0);
}

TEST(Obstacle, Plane) {
    Obstacle o;
    o.kind = ObstacleKind::plane;
    o.center = {1.0, 2.0, 3.0};
    o.extent = {0.0, 0.6, 0.8};  // unit, as the environment stores it
    const double r = 0.01;
    // A point 0.004 from the plane on the normal's side, moved along the plane too.
    const Vec3 along(0.5, 0.8, -0.6);  // in the plane: along . n = 0
    const Vec3 near(1.0 + along[0] + 0.004 * 0.0, 2.0 + along[1] + 0.004 * 0.6,
                            3.0 + along[2] + 0.004 * 0.8);
    auto c = contacts_of(o, near, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.006, 1e-12);
    expect_normal(c[0], 0, 0.6, 0.8);
    // Behind the plane: deeper than R, still pushed toward the normal's side.
    const Vec3 behind(1.0, 2.0 - 0.003 * 0.6, 3.0 - 0.003 * 0.8);
    c = contacts_of(o, behind, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.013, 1e-12);
    expect_normal(c[0], 0, 0.6, 0.8);
    // Farther than R on the free side: nothing.
    const Vec3 away(1.0, 2.0 + 0.011 * 0.6, 3.0 + 0.011 * 0.8);
    EXPECT_TRUE(contacts_of(o, away, r).empty());
}

TEST(Obstacle, Sphere) {
    Obstacle o;
    o.kind = ObstacleKind::sphere;
    o.center = {0.1, 0.2, 0.3};
    o.radius = 0.05;
    const double r = 0.01;
    // 0.056 from the centre along (2, -1, 2) / 3: depth 0.05 + 0.01 - 0.056 = 0.004.
    const Vec3 p(0.1 + 0.056 * 2 / 3.0, 0.2 - 0.056 / 3.0, 0.3 + 0.056 * 2 / 3.0);
    auto c = contacts_of(o, p, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.004, 1e-12);
    expect_normal(c[0], 2 / 3.0, -1 / 3.0, 2 / 3.0);
    const Vec3 apart(0.1, 0.2, 0.3 + 0.0601);
    EXPECT_TRUE(contacts_of(o, apart, r).empty());
}

TEST(Obstacle, CapsuleInteriorEndsAndAxis) {
    Obstacle o;
    o.kind = ObstacleKind::capsule;
    o.center = {0.0, 0.0, 0.0};   // start
    o.extent = {0.0, 0.2, 0.0};   // end
    o.radius = 0.03;
    const double r = 0.01;
    // Beside the middle of the axis, 0.035 away along (0.6, 0, -0.8): depth 0.005.
    const Vec3 side(0.035 * 0.6, 0.13, -0.035 * 0.8);
    auto c = contacts_of(o, side, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.005, 1e-12);
    expect_normal(c[0], 0.6, 0.0, -0.8);
    // Beyond the end cap: measured from the end point, along (0, 0.8, 0.6).
    const Vec3 past_end(0.0, 0.2 + 0.032 * 0.8, 0.032 * 0.6);
    c = contacts_of(o, past_end, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.008, 1e-12);
    expect_normal(c[0], 0.0, 0.8, 0.6);
    // Before the start cap, straight along the axis.
    const Vec3 before_start(0.0, -0.037, 0.0);
    c = contacts_of(o, before_start, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.003, 1e-12);
    expect_normal(c[0], 0.0, -1.0, 0.0);
    // Beside the axis but farther than radius + r: nothing; near the end, off the cap: nothing.
    const Vec3 apart(0.0401, 0.1, 0.0);
    EXPECT_TRUE(contacts_of(o, apart, r).empty());
    const Vec3 off_cap(0.03, 0.2 + 0.03, 0.0);  // 0.0424 from the end point
    EXPECT_TRUE(contacts_of(o, off_cap, r).empty());
    // A centre on the axis: full depth, and some unit normal, never NaN.
    const Vec3 on_axis(0.0, 0.07, 0.0);
    c = contacts_of(o, on_axis, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.04, 1e-12);
    EXPECT_NEAR(c[0].normal.norm(), 1.0, 1e-12);
    // The same at the centre of a sphere obstacle.
    Obstacle s;
    s.kind = ObstacleKind::sphere;
    s.center = {0.0, 0.07, 0.0};
    s.radius = 0.03;
    c = contacts_of(s, on_axis, r);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].depth, 0.04, 1e-12);
    EXPECT_NEAR(c[0].normal.norm(), 1.0, 1e-12);
}

// ---- the contact law -------------------------------------------------------------------

// A unit normal not along any axis, and velocities made of normal and tangential parts.
const Vec3 kNormal(2 / 7.0, 3 / 7.0, 6 / 7.0);
const Vec3 kTangent(3 / 7.0, -6 / 7.0, 2 / 7.0);  // unit, orthogonal to kNormal

Vec3 velocity(double normal_speed, double tangential_speed) {
    return normal_speed * kNormal + tangential_speed * kTangent;
}

TEST(ContactForce, NeverPulls) {
    const ContactParameters p;  // 500 N/m, 0.5 N s/m
    const double depth = 0.001;
    // Separating fast: a damper on the whole normal speed would give 500 * 0.001 - 0.5 * 10
    // = -4.5 N, a pull; the law keeps the spring alone.
    for (double vn : {0.0, 0.1, 1.0, 10.0, 1e3}) {
        Vec3 v = velocity(vn, 0.05);
        const ContactForce f = contact_force(p, depth, kNormal, v);
        EXPECT_GE(f.normal_force, 0.0) << vn;
        EXPECT_GE(f.force.dot(kNormal), 0.0) << vn;
        EXPECT_NEAR(f.normal_force, p.stiffness * depth, 1e-12) << vn;
        EXPECT_NEAR(f.force.dot(kNormal), f.normal_force, 1e-12) << vn;
        EXPECT_EQ(f.damping, 0.0) << vn;
    }
}

TEST(ContactForce, DampsOnlyWhileApproaching) {
    const ContactParameters p;
    const double depth = 0.002;
    Vec3 v = velocity(-0.4, 0.0);  // approaching at 0.4 m/s
    ContactForce f = contact_force(p, depth, kNormal, v);
    EXPECT_NEAR(f.normal_force, p.stiffness * depth + p.damping * 0.4, 1e-12);
    EXPECT_EQ(f.damping, p.damping);
    EXPECT_EQ(f.stiffness, p.stiffness);
    v = velocity(+0.4, 0.0);  // separating at the same speed
    f = contact_force(p, depth, kNormal, v);
    EXPECT_NEAR(f.normal_force, p.stiffness * depth, 1e-12);
    EXPECT_EQ(f.damping, 0.0);
}

TEST(ContactForce, FrictionOpposesSlidingAndIsBoundedByCoulomb) {
    ContactParameters p;
    p.friction = 0.4;
    p.slip_speed = 0.01;
    const double depth = 0.003;
    for (double vn : {-0.2, 0.0, 0.3})
        for (double vt : {-5.0, -0.3, -0.01, -1e-4, 1e-4, 0.002, 0.01, 0.1, 2.0}) {
            Vec3 v = velocity(vn, vt);
            const ContactForce f = contact_force(p, depth, kNormal, v);
            const double fn = f.force.dot(kNormal);
            const Vec3 tangential = f.force - fn * kNormal;
            const double ft = tangential.dot(kTangent);
            // Along the sliding direction only, against it, at most mu f_n.
            EXPECT_NEAR(tangential.norm(), std::fabs(ft), 1e-12);
            EXPECT_LT(ft * vt, 0.0) << vn << " " << vt;
            EXPECT_LE(std::fabs(ft), p.friction * f.normal_force * (1.0 + 1e-12)) << vn << " " << vt;
            // Fast sliding: nearly the full Coulomb force; slow: viscous, about mu f_n vt / slip.
            if (std::fabs(vt) >= 100 * p.slip_speed) {
                EXPECT_GT(std::fabs(ft), 0.999 * p.friction * f.normal_force) << vn << " " << vt;
            }
            if (std::fabs(vt) <= 0.01 * p.slip_speed) {
                const double viscous = p.friction * f.normal_force * std::fabs(vt) / p.slip_speed;
                EXPECT_NEAR(std::fabs(ft), viscous, 1e-3 * viscous) << vn << " " << vt;
            }
        }
    // Without friction there is no tangential force at all.
    p.friction = 0.0;
    Vec3 v = velocity(-0.1, 1.0);
    const ContactForce f = contact_force(p, depth, kNormal, v);
    EXPECT_NEAR(f.force.dot(kTangent), 0.0, 1e-15);
}

// ---- the environment effect ------------------------------------------------------------

TEST(EnvironmentForce, AStraightAxisPressedIntoAPlaneGetsTheSumOfItsSpheresForces) {
    // A straight axis along x at height R - d above the plane z = 0: every sphere is d deep.
    const std::size_t n = 21;
    const double length = 0.4, d = 0.001;
    State state(std::pmr::new_delete_resource());
    state.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        state.q[3 * i] = length * double(i) / double(n - 1);
        state.q[3 * i + 2] = kRadius - d;
    }
    AxisModel model;
    model.control_points = n;
    model.rest_segment_length = length / double(n - 1);
    model.linear_density = 0.3;
    Obstacle plane;
    plane.kind = ObstacleKind::plane;
    plane.extent = {0.0, 0.0, 3.0};  // not unit: the effect normalises it
    const ContactParameters contact;
    CollisionSpheres axis_spheres(model.control_points, length, 0.5 * kRadius, kRadius, std::pmr::new_delete_resource());
    SphereLoads loads(axis_spheres, std::pmr::new_delete_resource());
    EnvironmentForce effect(axis_spheres, contact, {plane}, state, std::pmr::new_delete_resource(), loads);
    // What Dynamics does with the loads the contact effects share.
    const auto evaluate = [&](std::vector<double>& force) {
        loads.clear();
        effect.evaluate(state, force.data(), nullptr);
        loads.apply(force.data(), nullptr);
    };
    std::vector<double> force(3 * n, 0.0);
    evaluate(force);
    ContactSummary summary;
    effect.add_contacts(summary);
    const std::size_t spheres = 65;  // 0.4 / 0.00625 + 1
    EXPECT_EQ(summary.count, spheres);
    EXPECT_NEAR(summary.max_penetration, d, 1e-12);
    // The basis weights sum to one: the control points receive the spheres' total force.
    double fx = 0.0, fy = 0.0, fz = 0.0;
    for (std::size_t i = 0; i < n; ++i) fx += force[3 * i], fy += force[3 * i + 1], fz += force[3 * i + 2];
    EXPECT_NEAR(fz, double(spheres) * contact.stiffness * d, 1e-9);
    EXPECT_NEAR(fx, 0.0, 1e-12);
    EXPECT_NEAR(fy, 0.0, 1e-12);
    for (std::size_t i = 0; i < n; ++i) EXPECT_GT(force[3 * i + 2], 0.0) << "control point " << i;
    EXPECT_NEAR(effect.potential_energy(state), double(spheres) * 0.5 * contact.stiffness * d * d, 1e-12);

    // Lifted clear of the plane: no contact, no force, no energy.
    for (std::size_t i = 0; i < n; ++i) state.q[3 * i + 2] = kRadius + 1e-6;
    std::fill(force.begin(), force.end(), 0.0);
    evaluate(force);
    ContactSummary none;
    effect.add_contacts(none);
    EXPECT_EQ(none.count, 0u);
    EXPECT_EQ(*std::max_element(force.begin(), force.end()), 0.0);
    EXPECT_EQ(*std::min_element(force.begin(), force.end()), 0.0);
    EXPECT_EQ(effect.potential_energy(state), 0.0);

    // An obstacle added between two evaluations of the same state counts at once (the
    // contacts found for that placement are not reused).
    Obstacle floor_above = plane;
    floor_above.center = {0.0, 0.0, 2e-6};
    effect.add_obstacle(floor_above);
    evaluate(force);
    ContactSummary after;
    effect.add_contacts(after);
    EXPECT_EQ(after.count, spheres);
    EXPECT_GT(effect.potential_energy(state), 0.0);
}

}  // namespace
