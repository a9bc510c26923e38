// SPDX-License-Identifier: Apache-2.0
// The skin C API (ent_skin_*): exact axes through ENT_SHAPE_POINTS scenes, every method's
// accuracy and closure, no blending at a tight U-turn, a skin updated on a render thread
// while the physics thread steps, and bad input.
#include "skin_test_support.h"

#include <atomic>
#include <chrono>
#include <thread>

using namespace capi_test;
using namespace skin_test;

namespace {

constexpr double kSkinR = 0.0125;
constexpr double kSkinPi = 3.14159265358979323846;


// A scene whose axis is exactly the given control points (no effects: it never moves).
ScenePtr points_scene(const std::vector<double>& q) {
    ent_scene_desc desc = default_desc();
    desc.effects = 0;
    desc.shape = ENT_SHAPE_POINTS;
    desc.control_points = uint32_t(q.size() / 3);
    desc.shape_points_xyz_m = q.data();
    desc.radius_m = kSkinR;
    return create(desc);
}

std::vector<double> straight(int n, double spacing) {
    std::vector<double> q;
    for (int i = 0; i < n; ++i) q.insert(q.end(), {0.1 + i * spacing, -0.05, 0.02});
    return q;
}

std::vector<double> u_turn(double leg, double gap, double spacing) {
    std::vector<double> q;
    const double r = 0.5 * gap;
    const int legs = int(std::ceil(leg / spacing)), arc = int(std::ceil(kSkinPi * r / spacing));
    for (int i = 0; i < legs; ++i) q.insert(q.end(), {-leg + i * (leg / legs), -r, 0.0});
    for (int i = 0; i < arc; ++i) {
        const double a = -0.5 * kSkinPi + kSkinPi * i / arc;
        q.insert(q.end(), {r * std::cos(a), r * std::sin(a), 0.0});
    }
    for (int i = 0; i <= legs; ++i) q.insert(q.end(), {-i * (leg / legs), r, 0.0});
    return q;
}

const int32_t kMethods[] = {ENT_SKIN_TUBE, ENT_SKIN_POINT_SKELETON, ENT_SKIN_CONVOLUTION};

TEST(Skin, StraightTubeEveryMethodWithinHalfAPercent) {
    ScenePtr scene = points_scene(straight(41, 0.02));
    ASSERT_TRUE(scene);
    for (int32_t method : kMethods) {
        SkinPtr skin = make_skin(scene.get(), method);
        ASSERT_TRUE(skin);
        EXPECT_EQ(mesh(skin.get()).vertex_count, 0u);  // empty before the first update
        ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
        const ent_mesh_view view = mesh(skin.get());
        ASSERT_GT(view.triangle_count, 100u);
        EXPECT_EQ(view.updates, 1u);
        for (uint32_t i = 0; i < 3 * view.triangle_count; ++i) ASSERT_LT(view.indices[i], view.vertex_count);
        const struct ent_skin_metrics m = metrics(skin.get());
        EXPECT_EQ(m.vertex_count, view.vertex_count);
        EXPECT_LT(m.radius_error_rms, 0.005) << "method " << method;
        EXPECT_EQ(m.watertight, 1) << "method " << method;
        EXPECT_EQ(m.blended_vertices, 0u);
        EXPECT_NEAR(m.axis_length_m, 0.8, 1e-9);
    }
}

TEST(Skin, TightUTurnImplicitMethodsDoNotBlendTheLegs) {
    ScenePtr scene = points_scene(u_turn(0.15, 2.2 * kSkinR, 0.25 * kSkinR));
    ASSERT_TRUE(scene);
    for (int32_t method : {ENT_SKIN_POINT_SKELETON, ENT_SKIN_CONVOLUTION}) {
        SkinPtr skin = make_skin(scene.get(), method);
        ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
        const struct ent_skin_metrics m = metrics(skin.get());
        EXPECT_EQ(m.blended_vertices, 0u) << "method " << method;
        EXPECT_EQ(m.watertight, 1) << "method " << method;
    }
    // The tube stays exact at this bend (radius of curvature 1.1 R); at a tighter one its
    // rings would fold over on the inner side, and stop short of each other instead.
    SkinPtr tube = make_skin(scene.get(), ENT_SKIN_TUBE);
    ASSERT_EQ(ent_skin_update(tube.get()), ENT_OK);
    EXPECT_EQ(metrics(tube.get()).inverted_triangles, 0u);
    ScenePtr tight = points_scene(u_turn(0.15, 1.4 * kSkinR, 0.25 * kSkinR));
    SkinPtr folded = make_skin(tight.get(), ENT_SKIN_TUBE);
    ASSERT_EQ(ent_skin_update(folded.get()), ENT_OK);
    EXPECT_EQ(metrics(folded.get()).inverted_triangles, 0u);
    EXPECT_GT(metrics(folded.get()).overlap_depth_max, 0.3);  // its legs pass through each other
}

TEST(Skin, RenderThreadUpdatesWhileThePhysicsThreadSteps) {
    ent_scene_desc desc = default_desc();  // stretch, bend, damping, gravity
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);  // hangs, swings, and does not fall forever
    desc.length_m = 1.0;
    desc.control_points = 40;
    desc.shape = ENT_SHAPE_HELIX;
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    SkinPtr skin = make_skin(scene.get(), ENT_SKIN_CONVOLUTION);
    ASSERT_TRUE(skin);

    std::atomic<bool> done{false};
    std::atomic<long> updates{0}, bad{0};
    std::thread render([&] {
        double last_time = -1.0;
        while (!done.load()) {
            if (ent_skin_update(skin.get()) != ENT_OK) {
                ++bad;
                continue;
            }
            const ent_mesh_view view = mesh(skin.get());
            bool ok = view.vertex_count > 0 && view.time_s >= last_time;
            for (uint32_t i = 0; ok && i < 3 * view.triangle_count; ++i) ok = view.indices[i] < view.vertex_count;
            for (uint32_t i = 0; ok && i < 3 * view.vertex_count; ++i) ok = std::isfinite(view.positions_xyz_m[i]);
            for (uint32_t i = 0; ok && i < view.vertex_count; ++i) ok = view.axis_u[i] >= 0.0f && view.axis_u[i] <= 1.0f;
            if (!ok) ++bad;
            last_time = view.time_s;
            ++updates;
        }
    });
    const auto start = std::chrono::steady_clock::now();
    long steps = 0;
    while (std::chrono::steady_clock::now() - start < std::chrono::seconds(5)) {
        const ent_status status = ent_scene_step(scene.get(), 1e-3);
        EXPECT_EQ(status, ENT_OK) << ent_last_error();
        if (status != ENT_OK) break;
        ++steps;
    }
    done = true;
    render.join();
    EXPECT_EQ(bad.load(), 0);
    EXPECT_GT(updates.load(), 10);
    EXPECT_GT(steps, 100);
    // The last mesh is still a closed tube around the moved axis.
    ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK);
    const struct ent_skin_metrics m = metrics(skin.get());
    EXPECT_EQ(m.watertight, 1);
    EXPECT_LT(m.free_radius_error_rms, 0.05);  // away from the coils' contacts
}

}  // namespace
