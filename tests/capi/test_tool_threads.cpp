// SPDX-License-Identifier: Apache-2.0
// The haptic thread and the physics thread (issue 16, defect 4): a tool's commands (pose,
// grasp, release) are posted from any thread without a lock and taken by the next step, the
// last one posted winning; its output (wrench, grasp, contacts) is read from the published
// snapshot by any thread. thread_stress (run under ThreadSanitizer) races the same calls at
// 1 kHz; these tests check what they mean.
#include "capi_scenes.h"

#include <atomic>
#include <chrono>
#include <thread>

#include "test_helpers.h"

using namespace capi_test;

namespace {

using enteron_test::kIdentity;

constexpr double kToolThreadsRadius = kBowelRadius;  // the default R, m

// A 0.4 m bowel on the floor and a tool resting on its middle.
ScenePtr bowel_with_tool(double max_force = 5.0) {
    ScenePtr scene = bowel_on_plane(BowelOnPlane{});
    if (!scene) return scene;
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    tool.position_m[2] = 2 * kToolThreadsRadius + 0.004;
    tool.max_force_N = max_force;
    EXPECT_EQ(ent_tool_add(scene.get(), &tool, nullptr), ENT_OK) << ent_last_error();
    return scene;
}

ent_tool_feedback tool_threads_feedback(const ent_scene* scene) {
    ent_tool_feedback f;
    std::memset(&f, 0, sizeof f);
    f.struct_size = sizeof f;
    EXPECT_EQ(ent_tool_read_feedback(scene, 0, &f), ENT_OK) << ent_last_error();
    return f;
}

TEST(ToolThreads, TheLastPoseBeforeAStepWins) {
    ScenePtr many = bowel_with_tool(), last = bowel_with_tool();
    ASSERT_TRUE(many && last);
    const double a[3] = {0.05, 0.0, 0.03}, b[3] = {-0.02, 0.01, 0.02}, c[3] = {0.0, -0.01, 0.027};
    for (const double* p : {a, b, c}) ASSERT_EQ(ent_tool_set_pose(many.get(), 0, p, kIdentity), ENT_OK);
    ASSERT_EQ(ent_tool_set_pose(last.get(), 0, c, kIdentity), ENT_OK);
    ASSERT_TRUE(step_n(many.get(), 1e-3, 20));
    ASSERT_TRUE(step_n(last.get(), 1e-3, 20));
    const std::vector<double> x = control_points(many.get()), y = control_points(last.get());
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0);
    const ent_tool_feedback f = tool_threads_feedback(many.get()), g = tool_threads_feedback(last.get());
    EXPECT_EQ(std::memcmp(f.force_N, g.force_N, sizeof f.force_N), 0);
}

TEST(ToolThreads, TheLastGraspOrReleaseBeforeAStepWins) {
    ScenePtr scene = bowel_with_tool();
    ASSERT_TRUE(scene);
    ASSERT_EQ(ent_tool_grasp(scene.get(), 0), ENT_OK);
    ASSERT_EQ(ent_tool_release(scene.get(), 0), ENT_OK);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 1));
    EXPECT_EQ(tool_threads_feedback(scene.get()).grasping, 0) << "the release came last";
    ASSERT_EQ(ent_tool_release(scene.get(), 0), ENT_OK);
    ASSERT_EQ(ent_tool_grasp(scene.get(), 0), ENT_OK);
    EXPECT_EQ(tool_threads_feedback(scene.get()).grasping, 0) << "not before the step takes it";
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 1));
    EXPECT_EQ(tool_threads_feedback(scene.get()).grasping, 1) << "the grasp came last";
}

TEST(ToolThreads, TheFeedbackIsOneSnapshotsWrenchGraspAndContacts) {
    ScenePtr scene = bowel_with_tool();
    ASSERT_TRUE(scene);
    ent_tool_feedback f = tool_threads_feedback(scene.get());
    EXPECT_EQ(f.steps, 0u);
    EXPECT_EQ(f.time_s, 0.0);
    EXPECT_EQ(f.contacts, 0u) << "nothing was evaluated before the first step";
    const double pressed[3] = {0.0, 0.0, 2 * kToolThreadsRadius - 0.004};  // 4 mm into the bowel
    ASSERT_EQ(ent_tool_set_pose(scene.get(), 0, pressed, kIdentity), ENT_OK);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 30));
    f = tool_threads_feedback(scene.get());
    EXPECT_EQ(f.steps, 30u);
    EXPECT_NEAR(f.time_s, 0.030, 1e-15);
    EXPECT_GT(f.contacts, 0u);
    EXPECT_GT(f.force_N[2], 0.0) << "the bowel pushes the tool up";
    double force[3], torque[3];
    int32_t grasping = -1;
    ASSERT_EQ(ent_tool_wrench(scene.get(), 0, force, torque), ENT_OK);
    ASSERT_EQ(ent_tool_state(scene.get(), 0, &grasping), ENT_OK);
    EXPECT_EQ(std::memcmp(force, f.force_N, sizeof force), 0);
    EXPECT_EQ(std::memcmp(torque, f.torque_Nm, sizeof torque), 0);
    EXPECT_EQ(grasping, f.grasping);
}

TEST(ToolThreads, AHapticThreadAt1kHzBesideThePhysicsThread) {
    // The physics thread steps 1 ms steps as fast as it can; the haptic thread, at 1 kHz,
    // posts the device's pose (a slow circle pressing on the bowel) and reads the feedback.
    // No call fails, no feedback is torn (time = steps x dt), none goes back in time, every
    // force is within max_force, and the haptic thread never waits for a step.
    constexpr double kMaxForce = 2.0;
    ScenePtr scene = bowel_with_tool(kMaxForce);
    ASSERT_TRUE(scene);
    std::atomic<bool> done{false};
    std::atomic<long> failures{0}, torn{0}, backwards{0}, over{0}, ticks{0};
    std::thread haptic([&] {
        uint64_t last_steps = 0;
        auto next = std::chrono::steady_clock::now();
        for (long tick = 0; !done.load(); ++tick) {
            const double angle = 0.01 * double(tick);
            const double p[3] = {0.02 * std::cos(angle), 0.02 * std::sin(angle), 2 * kToolThreadsRadius - 0.002};
            if (ent_tool_set_pose(scene.get(), 0, p, kIdentity) != ENT_OK) ++failures;
            if (tick % 500 == 250 && ent_tool_grasp(scene.get(), 0) != ENT_OK) ++failures;
            if (tick % 500 == 0 && ent_tool_release(scene.get(), 0) != ENT_OK) ++failures;
            ent_tool_feedback f;
            f.struct_size = sizeof f;
            if (ent_tool_read_feedback(scene.get(), 0, &f) != ENT_OK) {
                ++failures;
            } else {
                if (std::fabs(f.time_s - 1e-3 * double(f.steps)) > 1e-9 * (1.0 + f.time_s)) ++torn;
                if (f.steps < last_steps) ++backwards;
                last_steps = f.steps;
                const double magnitude =
                    std::sqrt(f.force_N[0] * f.force_N[0] + f.force_N[1] * f.force_N[1] + f.force_N[2] * f.force_N[2]);
                if (!(magnitude <= kMaxForce * (1 + 1e-12))) ++over;
            }
            ++ticks;
            next += std::chrono::milliseconds(1);
            std::this_thread::sleep_until(next);
        }
    });
    long steps = 0;
    while (ticks.load() < 300 || steps < 300) {
        ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << ent_last_error();
        ++steps;
    }
    done = true;
    haptic.join();
    EXPECT_EQ(failures.load(), 0);
    EXPECT_EQ(torn.load(), 0);
    EXPECT_EQ(backwards.load(), 0);
    EXPECT_EQ(over.load(), 0);
    EXPECT_EQ(tool_threads_feedback(scene.get()).steps, uint64_t(steps));
    for (double v : control_points(scene.get())) ASSERT_TRUE(std::isfinite(v));
}

}  // namespace
