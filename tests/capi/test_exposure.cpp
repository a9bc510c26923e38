// SPDX-License-Identifier: Apache-2.0
// ent_scene_exposure against analytic occlusion: a straight tube of radius R at height h
// above a plane, seen from an eye at height H straight above the tube. A point p of the
// plane is hidden when its sight line passes within R of the axis; for a tube along x, in
// the y-z plane that is when |p_y| (H - h) / sqrt(p_y^2 + H^2) < R, a band |p_y| < w with
// w = R H / sqrt((H - h)^2 - R^2). A disk on the band's edge is half covered, inside the
// band fully covered, beyond it not covered. A tube tilted out of the plane by theta casts a
// band between the two planes through the eye tangent to the cylinder.
#include "capi_test_support.h"

#include <atomic>
#include <thread>

using namespace capi_test;

namespace {

constexpr double kR = 0.0125;  // tube radius, m
constexpr double kH = 0.30;    // eye height, m
constexpr double kh = 0.05;    // axis height, m

struct ExposureDeleter {
    void operator()(ent_exposure* e) const { ent_exposure_destroy(e); }
};
using ExposurePtr = std::unique_ptr<ent_exposure, ExposureDeleter>;

// A straight 2 m tube through `center` along `direction` (unit), at rest, no effect that moves it.
ScenePtr straight_tube(const double center[3], const double direction[3]) {
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND);
    desc.shape = ENT_SHAPE_LINE;
    desc.length_m = 2.0;
    desc.control_points = 81;
    desc.radius_m = kR;
    for (int c = 0; c < 3; ++c) {
        desc.shape_center_m[c] = center[c] - 1.0 * direction[c];
        desc.shape_direction[c] = direction[c];
    }
    return create(desc);
}

// A regular 64-gon of radius rho around (cx, cy) in the plane z = 0, as a fan of triangles.
struct Patch {
    std::vector<double> points;
    std::vector<uint32_t> triangles;
};
Patch disk(double cx, double cy, double rho) {
    Patch p;
    p.points = {cx, cy, 0.0};
    const int sides = 64;
    for (int k = 0; k < sides; ++k) {
        const double a = 2.0 * M_PI * (k + 0.5) / sides;  // symmetric about the x and y axes
        p.points.insert(p.points.end(), {cx + rho * std::cos(a), cy + rho * std::sin(a), 0.0});
        p.triangles.insert(p.triangles.end(), {0u, uint32_t(1 + k), uint32_t(1 + (k + 1) % sides)});
    }
    return p;
}

ExposurePtr make_exposure(const ent_scene* scene, const std::vector<double>& points,
                          const std::vector<uint32_t>& triangles, uint32_t samples_per_edge = 8,
                          const double* weights = nullptr, int32_t obstacle = ENT_NO_OBSTACLE) {
    ent_exposure_desc desc;
    ent_exposure_desc_default(&desc);
    desc.points_xyz_m = points.data();
    desc.point_count = uint32_t(points.size() / 3);
    desc.triangles = triangles.empty() ? nullptr : triangles.data();
    desc.triangle_count = uint32_t(triangles.size() / 3);
    desc.samples_per_edge = samples_per_edge;
    desc.weights = weights;
    desc.obstacle = obstacle;
    ent_exposure* e = nullptr;
    EXPECT_EQ(ent_exposure_create(scene, &desc, &e), ENT_OK) << ent_last_error();
    return ExposurePtr(e);
}

struct Measured {
    ent_exposure_result result;
    std::vector<double> spans;      // 2 per span
    std::vector<double> fractions;  // hidden by each span
    std::vector<int32_t> tubes;
    std::vector<double> elements;
};

Measured measure(const ent_scene* scene, ent_exposure* e, std::size_t elements, const double eye[3]) {
    Measured m;
    m.spans.resize(2 * 16);
    m.fractions.resize(16);
    m.tubes.resize(16);
    m.elements.resize(elements);
    std::memset(&m.result, 0, sizeof m.result);
    m.result.struct_size = sizeof m.result;
    m.result.span_capacity = 16;
    m.result.spans_u = m.spans.data();
    m.result.span_hidden_fractions = m.fractions.data();
    m.result.span_intestines = m.tubes.data();
    m.result.element_visible = m.elements.data();
    EXPECT_EQ(ent_scene_exposure(scene, e, eye, &m.result), ENT_OK) << ent_last_error();
    return m;
}

const double kEye[3] = {0.0, 0.0, kH};
const double kAlongX[3] = {1.0, 0.0, 0.0};
const double kAxisCenter[3] = {0.0, 0.0, kh};

double band_half_width() { return kR * kH / std::sqrt((kH - kh) * (kH - kh) - kR * kR); }

}  // namespace

TEST(Exposure, EachPointIsHiddenExactlyWhereTheAnalyticBandSaysSo) {
    ScenePtr scene = straight_tube(kAxisCenter, kAlongX);
    // A grid of points across the band and beyond it.
    std::vector<double> points;
    for (int i = -10; i <= 10; ++i)
        for (int j = -40; j <= 40; ++j) points.insert(points.end(), {0.004 * i, 0.001 * j + 0.00037, 0.0});
    ExposurePtr e = make_exposure(scene.get(), points, {});
    const Measured m = measure(scene.get(), e.get(), points.size() / 3, kEye);
    std::size_t hidden = 0;
    for (std::size_t k = 0; k < points.size() / 3; ++k) {
        const double y = points[3 * k + 1];
        const bool analytic_hidden = std::abs(y) * (kH - kh) / std::sqrt(y * y + kH * kH) < kR;
        EXPECT_EQ(m.elements[k], analytic_hidden ? 0.0 : 1.0) << "point (" << points[3 * k] << ", " << y << ")";
        hidden += analytic_hidden ? 1 : 0;
    }
    EXPECT_EQ(m.result.hidden_samples, hidden);
    EXPECT_GT(hidden, 0u);
    EXPECT_NEAR(m.result.visible_fraction, 1.0 - double(hidden) / double(points.size() / 3), 1e-12);
}

TEST(Exposure, ADiskOnTheBandsEdgeIsHalfCoveredInsideItFullyBeyondItNot) {
    ScenePtr scene = straight_tube(kAxisCenter, kAlongX);
    const double w = band_half_width();
    const double rho = 0.01;
    struct Case {
        const char* name;
        double center_y;
        double expected;
    } cases[] = {{"half covered", w, 0.5}, {"fully covered", 0.0, 0.0}, {"not covered", w + rho + 0.003, 1.0}};
    for (const Case& c : cases) {
        const Patch p = disk(0.0, c.center_y, rho);
        ExposurePtr e = make_exposure(scene.get(), p.points, p.triangles, 8);
        const Measured m = measure(scene.get(), e.get(), p.triangles.size() / 3, kEye);
        EXPECT_NEAR(m.result.visible_fraction, c.expected, 0.01) << c.name;
        EXPECT_EQ(m.result.samples, 64u * 64u) << c.name;
        std::printf("%s: visible %.4f (analytic %.1f), %u spans\n", c.name, m.result.visible_fraction, c.expected,
                    m.result.span_count);
        if (c.expected == 1.0) {
            EXPECT_EQ(m.result.span_count, 0u) << c.name;
            continue;
        }
        // One span, around the disk's shadow on the axis: sight lines to x in [-rho, rho]
        // cross the axis' height at x (H - h) / H; the span reaches R (plus a chord of 6 mm)
        // beyond.
        ASSERT_EQ(m.result.span_count, 1u) << c.name;
        EXPECT_EQ(m.tubes[0], 0);
        const double reach = rho * (kH - kh) / kH;
        const double u_center = 0.5, length = 2.0, slack = (kR + 0.0065) / length;
        EXPECT_LE(m.spans[0], u_center - reach / length + 1e-9) << c.name;
        EXPECT_GE(m.spans[0], u_center - reach / length - slack) << c.name;
        EXPECT_GE(m.spans[1], u_center + reach / length - 1e-9) << c.name;
        EXPECT_LE(m.spans[1], u_center + reach / length + slack) << c.name;
        EXPECT_NEAR(m.fractions[0], 1.0 - m.result.visible_fraction, 1e-12) << c.name;
    }
}

TEST(Exposure, TheHalfCoveredDiskConvergesAsItsSamplesGetFiner) {
    ScenePtr scene = straight_tube(kAxisCenter, kAlongX);
    const Patch p = disk(0.0, band_half_width(), 0.01);
    double previous_error = 1.0;
    for (uint32_t n : {2u, 8u, 32u}) {
        ExposurePtr e = make_exposure(scene.get(), p.points, p.triangles, n);
        const double error = std::abs(measure(scene.get(), e.get(), 64, kEye).result.visible_fraction - 0.5);
        std::printf("half covered, %u samples per edge: |visible - 0.5| = %.5f\n", n, error);
        EXPECT_LE(error, previous_error + 1e-12) << n << " samples per edge";
        previous_error = error;
    }
    EXPECT_LT(previous_error, 0.003);
}

TEST(Exposure, ATubeTiltedOutOfThePlaneHalfCoversADiskOnItsShadowsEdge) {
    // The axis through (0, 0, h) along (cos t, 0, sin t). The planes through the eye tangent
    // to the cylinder contain its direction; their normals n = a (-sin t, 0, cos t) + b (0, 1, 0)
    // with a = R / ((H - h) cos t) and b = sqrt(1 - a^2) meet the plane z = 0 on the lines
    // y = +-(a / b) (x sin t + H cos t): the shadow's edges.
    const double theta = 20.0 * M_PI / 180.0;
    const double direction[3] = {std::cos(theta), 0.0, std::sin(theta)};
    ScenePtr scene = straight_tube(kAxisCenter, direction);
    const double a = kR / ((kH - kh) * std::cos(theta)), b = std::sqrt(1.0 - a * a);
    const double edge_y = (a / b) * kH * std::cos(theta);
    // The edge line is straight through the disk's centre: half its area on each side.
    const Patch p = disk(0.0, edge_y, 0.008);
    ExposurePtr e = make_exposure(scene.get(), p.points, p.triangles, 16);
    const Measured m = measure(scene.get(), e.get(), 64, kEye);
    EXPECT_NEAR(m.result.visible_fraction, 0.5, 0.01);
    std::printf("tilted 20 degrees: visible %.4f (analytic 0.5)\n", m.result.visible_fraction);
    // Points of the grid hidden exactly where the shadow's edges say.
    std::vector<double> points;
    for (int i = -8; i <= 8; ++i)
        for (int j = -30; j <= 30; ++j) points.insert(points.end(), {0.005 * i, 0.001 * j + 0.00041, 0.0});
    ExposurePtr grid = make_exposure(scene.get(), points, {});
    const Measured g = measure(scene.get(), grid.get(), points.size() / 3, kEye);
    for (std::size_t k = 0; k < points.size() / 3; ++k) {
        const double x = points[3 * k], y = points[3 * k + 1];
        const bool analytic_hidden = std::abs(y) < (a / b) * (x * std::sin(theta) + kH * std::cos(theta));
        EXPECT_EQ(g.elements[k], analytic_hidden ? 0.0 : 1.0) << "point (" << x << ", " << y << ")";
    }
}

TEST(Exposure, WeightsCountAndAWeightlessPointCountsForNothing) {
    ScenePtr scene = straight_tube(kAxisCenter, kAlongX);
    // One point under the tube (hidden), two beyond the band (seen), weights 3, 1, 0.
    const std::vector<double> points = {0.0, 0.0, 0.0, 0.0, 0.05, 0.0, 0.0, -0.05, 0.0};
    const double weights[3] = {3.0, 1.0, 0.0};
    ExposurePtr e = make_exposure(scene.get(), points, {}, 1, weights);
    const Measured m = measure(scene.get(), e.get(), 3, kEye);
    EXPECT_DOUBLE_EQ(m.result.visible_fraction, 0.25);
    EXPECT_EQ(m.result.hidden_samples, 1u);
}

TEST(Exposure, ATargetOnAnObstacleMovesWithIt) {
    ScenePtr scene = straight_tube(kAxisCenter, kAlongX);
    ent_obstacle_desc plane;
    ent_obstacle_desc_default(&plane);
    plane.kind = ENT_OBSTACLE_PLANE;
    plane.center_m[2] = -0.1;
    int32_t obstacle = -1;
    ASSERT_EQ(ent_scene_add_obstacle(scene.get(), &plane, &obstacle), ENT_OK) << ent_last_error();
    // One point at the obstacle's origin: under the tube (hidden).
    const std::vector<double> points = {0.0, 0.0, 0.0};
    ExposurePtr e = make_exposure(scene.get(), points, {}, 1, nullptr, obstacle);
    EXPECT_EQ(measure(scene.get(), e.get(), 1, kEye).result.visible_fraction, 0.0);
    // The obstacle (and the point on it) moves 8 cm sideways: out of the shadow.
    const double moved[3] = {0.0, 0.08, 0.0}, identity[4] = {1.0, 0.0, 0.0, 0.0};
    ASSERT_EQ(ent_obstacle_set_pose(scene.get(), obstacle, moved, identity), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_scene_step(scene.get(), 0.001), ENT_OK) << ent_last_error();
    const Measured m = measure(scene.get(), e.get(), 1, kEye);
    EXPECT_EQ(m.result.visible_fraction, 1.0);
    EXPECT_EQ(m.result.steps, 1u);
    // Removed, the frame is gone: NOT_FOUND, nothing written.
    ASSERT_EQ(ent_scene_remove_obstacle(scene.get(), obstacle), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_scene_step(scene.get(), 0.001), ENT_OK) << ent_last_error();
    ent_exposure_result r{};
    r.struct_size = sizeof r;
    r.visible_fraction = -7.0;
    EXPECT_EQ(ent_scene_exposure(scene.get(), e.get(), kEye, &r), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(r.visible_fraction, -7.0);
}

TEST(Exposure, TwoLoopsAreTwoSpansEachWithTheFractionItHides) {
    // A U-shaped bowel: two parallel legs 6 cm apart at height h, joined far away; a wide
    // strip of points under both legs. Each leg is its own span.
    std::vector<double> shape;
    const uint32_t n = 120;
    const double leg = 1.4, turn = M_PI * 0.03, length = 2 * leg + turn;
    for (uint32_t i = 0; i < n; ++i) {
        const double s = length * i / (n - 1);  // out along y = -3 cm, a half turn, back along y = +3 cm
        double x = 0.0, y = 0.0;
        if (s < leg) {
            x = -0.7 + s, y = -0.03;
        } else if (s < leg + turn) {
            const double a = (s - leg) / 0.03 - M_PI / 2;
            x = 0.7 + 0.03 * std::cos(a), y = 0.03 * std::sin(a);
        } else {
            x = 0.7 - (s - leg - turn), y = 0.03;
        }
        shape.insert(shape.end(), {x, y, kh});
    }
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH);
    desc.shape = ENT_SHAPE_POINTS;
    desc.shape_points_xyz_m = shape.data();
    desc.control_points = n;
    desc.length_m = length;
    desc.radius_m = kR;
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    std::vector<double> points;
    for (int i = -5; i <= 5; ++i)
        for (int j = -60; j <= 60; ++j) points.insert(points.end(), {0.002 * i, 0.001 * j + 0.0003, 0.0});
    ExposurePtr e = make_exposure(scene.get(), points, {});
    const Measured m = measure(scene.get(), e.get(), points.size() / 3, kEye);
    ASSERT_EQ(m.result.span_count, 2u);
    EXPECT_LT(m.spans[1], 0.5);  // the first leg, out
    EXPECT_GT(m.spans[2], 0.5);  // the second, back
    // Each leg hides the points of its own band (half of the hidden ones, by symmetry).
    const double hidden = 1.0 - m.result.visible_fraction;
    EXPECT_GT(hidden, 0.1);
    EXPECT_NEAR(m.fractions[0], hidden / 2, 0.02);
    EXPECT_NEAR(m.fractions[1], hidden / 2, 0.02);
    EXPECT_NEAR(m.fractions[0] + m.fractions[1], hidden, 1e-9);  // no sight line crosses both
    // Only the first span is written with a capacity of 1; span_count still says 2.
    ent_exposure_result one{};
    double span[2] = {-1, -1};
    one.struct_size = sizeof one;
    one.span_capacity = 1;
    one.spans_u = span;
    ASSERT_EQ(ent_scene_exposure(scene.get(), e.get(), kEye, &one), ENT_OK) << ent_last_error();
    EXPECT_EQ(one.span_count, 2u);
    EXPECT_EQ(span[0], m.spans[0]);
    EXPECT_EQ(span[1], m.spans[1]);
}

TEST(Exposure, AnExposureOfAnotherSceneIsRefused) {
    ScenePtr scene = straight_tube(kAxisCenter, kAlongX);
    ScenePtr other = straight_tube(kAxisCenter, kAlongX);
    const std::vector<double> points = {0.0, 0.0, 0.0};
    ExposurePtr e = make_exposure(scene.get(), points, {});
    ent_exposure_result r{};
    r.struct_size = sizeof r;
    EXPECT_EQ(ent_scene_exposure(other.get(), e.get(), kEye, &r), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(ent_last_error()).find("another scene"), std::string::npos) << ent_last_error();
}

TEST(Exposure, QueriesFromAnotherThreadWhileTheSceneStepsSeeWholeStates) {
    // A falling bowel: each query sees one published state, its fraction in [0, 1] and its
    // steps never going back.
    ent_scene_desc desc = default_desc();
    desc.shape = ENT_SHAPE_LINE;
    desc.length_m = 1.0;
    desc.control_points = 40;
    for (int c = 0; c < 3; ++c) desc.shape_center_m[c] = kAxisCenter[c] - 0.5 * kAlongX[c];
    ScenePtr scene = create(desc);
    const Patch p = disk(0.0, 0.0, 0.02);
    ExposurePtr e = make_exposure(scene.get(), p.points, p.triangles, 4);
    std::atomic<bool> done{false};
    std::atomic<int> failures{0};
    std::thread reader([&] {
        uint64_t last_steps = 0;
        ent_exposure_result r{};
        r.struct_size = sizeof r;
        while (!done.load()) {
            if (ent_scene_exposure(scene.get(), e.get(), kEye, &r) != ENT_OK || r.visible_fraction < 0.0 ||
                r.visible_fraction > 1.0 || r.steps < last_steps)
                failures.fetch_add(1);
            last_steps = r.steps;
        }
    });
    for (int i = 0; i < 300; ++i) ASSERT_EQ(ent_scene_step(scene.get(), 0.001), ENT_OK) << ent_last_error();
    done.store(true);
    reader.join();
    EXPECT_EQ(failures.load(), 0);
}
