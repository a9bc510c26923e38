// SPDX-License-Identifier: Apache-2.0
// Overlapping driving calls (issue 16, defect 3). Two threads stepping one scene used to hang
// in the near-pair search or publish control points at 1e152 m; now a driving call made
// while another runs on the same scene returns ENT_ERROR_BUSY at once, with a message, and
// changes nothing.
//
// The overlap is made certain, not left to luck: the scene's log callback runs inside the
// first thread's driving call (a step the guard retries logs a warning; adding an obstacle
// or a tool logs the new substep limit), and there it hands a driving call to a second
// thread and waits for its answer.
#include "capi_test_support.h"

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

using namespace capi_test;

namespace {

// A second thread that makes one driving call when asked, from inside the first's call.
class SecondDriver {
public:
    explicit SecondDriver(std::function<ent_status()> call) : call_(std::move(call)), thread_([this] { busy_run(); }) {}
    ~SecondDriver() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            quit_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }

    // From now on, the next log line makes the overlap (creating the scene logs too).
    void arm() {
        std::lock_guard<std::mutex> lock(mutex_);
        armed_ = true;
    }

    // Called by the log callback on the first thread: the second call runs and returns
    // while the first is still inside the library.
    void call_now() {
        std::unique_lock<std::mutex> lock(mutex_);
        if (!armed_ || answered_) return;  // one overlap per test is enough
        asked_ = true;
        wake_.notify_all();
        wake_.wait(lock, [this] { return answered_; });
    }

    bool answered() {
        std::lock_guard<std::mutex> lock(mutex_);
        return answered_;
    }
    ent_status status() const { return status_; }
    const std::string& message() const { return message_; }

private:
    void busy_run() {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return asked_ || quit_; });
        if (quit_) return;
        lock.unlock();
        status_ = call_();
        message_ = ent_last_error();  // per thread: this thread's
        lock.lock();
        answered_ = true;
        wake_.notify_all();
    }

    std::function<ent_status()> call_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool armed_ = false, asked_ = false, answered_ = false, quit_ = false;
    ent_status status_ = -1;
    std::string message_;
    std::thread thread_;
};

void overlap_on_log(void* user, int32_t, const char*) { static_cast<SecondDriver*>(user)->call_now(); }

// The falling bowel of test_unstable.cpp: its first attempt breaks the speed limit, the
// guard retries (and logs) and the second attempt passes.
ent_scene_desc retried_step(ent_callbacks* callbacks) {
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) | ENT_EFFECT_BIT(ENT_EFFECT_DAMPING);
    desc.control_points = 10;
    desc.length_m = 1.0;
    desc.shape = ENT_SHAPE_LINE;
    desc.integrator = ENT_INTEGRATOR_SYMPLECTIC_EULER;
    desc.timestep_s = 0.01;
    desc.drag_N_s_per_m2 = 3.0;
    desc.stretch_damping_N_s = 0.0;
    desc.max_speed_m_per_s = 0.097;
    desc.callbacks = callbacks;
    return desc;
}

ent_callbacks busy_logging_to(SecondDriver& driver) {
    ent_callbacks callbacks;
    ent_callbacks_default(&callbacks);
    callbacks.log = overlap_on_log;
    callbacks.user_data = &driver;
    return callbacks;
}

void expect_busy(SecondDriver& second, const char* call) {
    ASSERT_TRUE(second.answered()) << "the scene never logged during the first call: no overlap was made";
    EXPECT_EQ(second.status(), ENT_ERROR_BUSY) << second.message();
    EXPECT_EQ(second.message().rfind(std::string(call) + ": another thread is in a driving call on this scene", 0), 0u)
        << second.message();
}

TEST(Busy, AStepDuringAStepIsRefusedAndChangesNothing) {
    ent_scene* scene = nullptr;
    SecondDriver second([&] { return ent_scene_step(scene, 0.01); });
    ent_callbacks callbacks = busy_logging_to(second);
    const ent_scene_desc desc = retried_step(&callbacks);
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    ScenePtr owner(scene);
    second.arm();
    ASSERT_EQ(ent_scene_step(scene, 0.01), ENT_OK) << ent_last_error();
    expect_busy(second, "ent_scene_step");
    // One step happened, exactly as in a twin that nobody disturbed.
    ent_scene_desc quiet = retried_step(nullptr);
    ScenePtr twin = create(quiet);
    ASSERT_TRUE(step_n(twin.get(), 0.01, 1));
    const ent_stats s = stats(scene), t = stats(twin.get());
    EXPECT_EQ(s.steps, 1u);
    EXPECT_EQ(s.substeps, t.substeps);
    EXPECT_EQ(s.rollbacks, t.rollbacks);
    const std::vector<double> a = control_points(scene), b = control_points(twin.get());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
}

TEST(Busy, EveryDrivingCallIsRefusedDuringAnother) {
    struct Pair {
        const char* first;
        const char* second;
    };
    for (const Pair pair : {Pair{"ent_scene_add_obstacle", "ent_scene_step"},
                            Pair{"ent_scene_add_obstacle", "ent_tool_add"},
                            Pair{"ent_tool_add", "ent_scene_add_obstacle"},
                            Pair{"ent_scene_step", "ent_tool_add"}}) {
        SCOPED_TRACE(std::string(pair.first) + " then " + pair.second);
        ent_scene* scene = nullptr;
        ent_obstacle_desc floor;
        ent_obstacle_desc_default(&floor);
        floor.kind = ENT_OBSTACLE_PLANE;
        floor.center_m[2] = -0.5;
        ent_tool_desc tool;
        ent_tool_desc_default(&tool);
        tool.position_m[2] = 0.5;
        const auto call = [&](const std::string& name) {
            if (name == "ent_scene_step") return ent_scene_step(scene, 0.01);
            if (name == "ent_tool_add") return ent_tool_add(scene, &tool, nullptr);
            return ent_scene_add_obstacle(scene, &floor, nullptr);
        };
        SecondDriver second([&] { return call(pair.second); });
        ent_callbacks callbacks = busy_logging_to(second);
        const ent_scene_desc desc = retried_step(&callbacks);
        ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
        ScenePtr owner(scene);
        second.arm();
        ASSERT_EQ(call(pair.first), ENT_OK) << ent_last_error();
        expect_busy(second, pair.second);
        const ent_stats s = stats(scene);
        EXPECT_EQ(s.steps, std::string(pair.first) == "ent_scene_step" ? 1u : 0u) << "the refused call did nothing";
        int32_t grasping = 0;
        const bool has_tool = ent_tool_state(scene, 0, &grasping) == ENT_OK;
        EXPECT_EQ(has_tool, std::string(pair.first) == "ent_tool_add");
    }
}

TEST(Busy, TwoThreadsSteppingOneSceneNeitherHangNorCorruptIt) {
    // The case: a self-colliding pile, stepped by two threads at once. Every call
    // returns OK or BUSY, the steps that succeeded are all counted, and the state stays
    // finite and in the box.
    ent_scene_desc desc = default_desc();
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    desc.control_points = 60;
    desc.length_m = 1.5;
    desc.shape_helix_radius_m = 0.05;
    desc.shape_center_m[2] = -0.1;
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    ent_obstacle_desc box;
    ent_obstacle_desc_default(&box);
    box.half_extents_m[0] = box.half_extents_m[1] = box.half_extents_m[2] = 0.2;
    ASSERT_EQ(ent_scene_add_obstacle(scene.get(), &box, nullptr), ENT_OK) << ent_last_error();
    std::atomic<long> ok{0}, busy{0}, other{0};
    const auto drive = [&] {
        for (int i = 0; i < 1500; ++i) {
            const ent_status status = ent_scene_step(scene.get(), 1e-3);
            (status == ENT_OK ? ok : status == ENT_ERROR_BUSY ? busy : other) += 1;
        }
    };
    std::thread a(drive), b(drive);
    a.join();
    b.join();
    EXPECT_EQ(other.load(), 0);
    EXPECT_EQ(ok.load() + busy.load(), 3000);
    EXPECT_EQ(stats(scene.get()).steps, uint64_t(ok.load()));
    for (double v : control_points(scene.get())) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_LT(std::fabs(v), 0.3);
    }
    std::cout << "[ two drivers ] " << ok.load() << " steps made, " << busy.load() << " refused as busy\n";
}

}  // namespace
