// SPDX-License-Identifier: Apache-2.0
// The published snapshot: queries from other threads, while one thread steps, always see one
// whole published state. The scene is a rigid free fall (gravity only, symplectic Euler), in
// which every control point of any one published state has moved by the same amount since the
// start; a read that mixed two states would show points displaced differently.
#include "capi_test_support.h"

#include <atomic>
#include <thread>

using namespace capi_test;

namespace {

constexpr uint32_t kThreadsPoints = 30;
constexpr double kThreadsDt = 1e-3;

TEST(Threads, ReadersSeeWholeSnapshotsWhileTheSceneSteps) {
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
    desc.control_points = kThreadsPoints;
    desc.length_m = 1.0;
    desc.shape = ENT_SHAPE_LINE;
    desc.integrator = ENT_INTEGRATOR_SYMPLECTIC_EULER;
    desc.gravity_m_per_s2[0] = 1.0;
    desc.gravity_m_per_s2[2] = -9.81;
    desc.max_speed_m_per_s = 1e9;  // a long fall: past the default 50 m/s after 5 s
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    const std::vector<double> start = control_points(scene.get());

    std::atomic<bool> done{false};
    std::atomic<long> torn{0}, failures{0}, reads{0}, stale_or_backwards{0};

    auto reader = [&] {
        std::vector<double> q(3 * kThreadsPoints), axis(3 * 16);
        uint64_t last_steps = 0;
        while (!done.load()) {
            uint32_t count = 0;
            if (ent_scene_control_points(scene.get(), kThreadsPoints, q.data(), &count) != ENT_OK || count != kThreadsPoints) {
                ++failures;
                continue;
            }
            for (uint32_t i = 1; i < kThreadsPoints; ++i)
                for (int c = 0; c < 3; ++c) {
                    const double di = q[3 * i + c] - start[3 * i + c];
                    const double d0 = q[c] - start[c];
                    // Round-off grows with the distance fallen; consecutive states differ by
                    // g t dt, i.e. 2 dt / t of it, far above this tolerance.
                    if (std::fabs(di - d0) > 1e-11 * (1.0 + std::fabs(d0))) {
                        ++torn;
                        i = kThreadsPoints;
                        break;
                    }
                }
            ent_stats s;
            s.struct_size = sizeof s;
            if (ent_scene_stats(scene.get(), &s) != ENT_OK) {
                ++failures;
                continue;
            }
            // One snapshot's time and step count belong together.
            const double expected_time = double(s.steps) * kThreadsDt;
            if (std::fabs(s.time_s - expected_time) > 1e-9 * (1.0 + expected_time)) ++torn;
            if (s.steps < last_steps) ++stale_or_backwards;
            last_steps = s.steps;
            if (ent_scene_axis(scene.get(), 16, axis.data()) != ENT_OK) ++failures;
            // The intestines' readers read the same snapshots, concurrently with the step.
            int32_t intestines = 0;
            if (ent_scene_intestine_count(scene.get(), &intestines) != ENT_OK || intestines != 1) ++failures;
            if (ent_scene_intestine_axis(scene.get(), 0, 16, axis.data()) != ENT_OK) ++failures;
            ++reads;
        }
    };

    std::thread a(reader), b(reader);
    // Step at least 3000 times, and on until the readers have overlapped the stepping for a
    // while (a step takes microseconds; the readers may be slow to start).
    long steps = 0;
    while (steps < 3000 || (reads.load() < 2000 && steps < 2000000)) {
        if (ent_scene_step(scene.get(), kThreadsDt) != ENT_OK) {
            ADD_FAILURE() << "step " << steps << ": " << ent_last_error();
            break;
        }
        ++steps;
    }
    done = true;
    a.join();
    b.join();
    EXPECT_EQ(torn.load(), 0);
    EXPECT_EQ(failures.load(), 0);
    EXPECT_EQ(stale_or_backwards.load(), 0);
    EXPECT_GE(reads.load(), 2000) << "the readers barely ran: the test proves little";
    EXPECT_EQ(stats(scene.get()).steps, uint64_t(steps));
}

}  // namespace
