// SPDX-License-Identifier: Apache-2.0
// Calls in the wrong order (issue 16, defect 2): a skin that outlives its scene used to read
// freed memory and return ENT_OK; now it shares the published snapshots and keeps building
// from the last state the scene published. The scene's memory, allocator callbacks
// included, goes with the last of the scene and its skins. Run under AddressSanitizer by
// scripts/test, which turns any read of freed memory into a failure.
#include "capi_test_support.h"

#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <map>
#include <mutex>
#include <thread>

using namespace capi_test;

namespace {

struct LifetimesSkinDeleter {
    void operator()(ent_skin* skin) const { ent_skin_destroy(skin); }
};
using LifetimesSkinPtr = std::unique_ptr<ent_skin, LifetimesSkinDeleter>;

LifetimesSkinPtr lifetimes_make_skin(ent_scene* scene, int32_t method) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    desc.method = method;
    ent_skin* skin = nullptr;
    EXPECT_EQ(ent_skin_create(scene, &desc, &skin), ENT_OK) << ent_last_error();
    return LifetimesSkinPtr(skin);
}

ent_scene_desc falling_desc() {
    ent_scene_desc desc = default_desc();
    desc.control_points = 30;
    desc.length_m = 0.6;
    desc.shape_helix_radius_m = 0.04;
    return desc;
}

std::vector<float> positions(const ent_skin* skin, double* time_s = nullptr) {
    ent_mesh_view view;
    std::memset(&view, 0, sizeof view);
    view.struct_size = sizeof view;
    EXPECT_EQ(ent_skin_mesh(skin, &view), ENT_OK) << ent_last_error();
    if (time_s != nullptr) *time_s = view.time_s;
    return std::vector<float>(view.positions_xyz_m, view.positions_xyz_m + 3 * std::size_t{view.vertex_count});
}

TEST(Lifetimes, ASkinOutlivesItsSceneOnTheLastPublishedState) {
    for (int32_t method : {ENT_SKIN_TUBE, ENT_SKIN_POINT_SKELETON, ENT_SKIN_CONVOLUTION}) {
        SCOPED_TRACE(method);
        ent_scene* scene = nullptr;
        const ent_scene_desc desc = falling_desc();
        ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
        LifetimesSkinPtr skin = lifetimes_make_skin(scene, method);
        ASSERT_TRUE(step_n(scene, 1e-3, 50));
        ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
        double before_s = 0.0;
        const std::vector<float> before = positions(skin.get(), &before_s);
        ASSERT_FALSE(before.empty());

        ent_scene_destroy(scene);
        // The skin keeps working: the last published state (t = 50 ms), as often as asked.
        for (int i = 0; i < 3; ++i) {
            ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
            double after_s = 0.0;
            const std::vector<float> after = positions(skin.get(), &after_s);
            EXPECT_EQ(after_s, before_s);
            EXPECT_EQ(after, before) << "the same state gives the same mesh";
        }
        struct ent_skin_metrics metrics;
        std::memset(&metrics, 0, sizeof metrics);
        metrics.struct_size = sizeof metrics;
        EXPECT_EQ(ent_skin_metrics(skin.get(), &metrics), ENT_OK) << ent_last_error();
        EXPECT_GT(metrics.vertex_count, 0u);
    }
}

TEST(Lifetimes, ASkinMadeBeforeAnyUpdateOutlivesItsSceneToo) {
    ent_scene* scene = nullptr;
    const ent_scene_desc desc = falling_desc();
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    LifetimesSkinPtr a = lifetimes_make_skin(scene, ENT_SKIN_TUBE), b = lifetimes_make_skin(scene, ENT_SKIN_CONVOLUTION);
    ent_scene_destroy(scene);
    a.reset();  // the skins go in any order; the last one frees the snapshots
    ASSERT_EQ(ent_skin_update(b.get()), ENT_OK) << ent_last_error();
    EXPECT_FALSE(positions(b.get()).empty());
}

// Counts the caller's allocator: the scene's memory goes with the last of it and its skins.
struct LifetimesHeap {
    std::mutex mutex;
    std::map<void*, size_t> live;
};
void* heap_allocate(void* user, size_t size, size_t alignment) {
    LifetimesHeap& heap = *static_cast<LifetimesHeap*>(user);
    const size_t a = alignment < sizeof(void*) ? sizeof(void*) : alignment;
    void* p = std::aligned_alloc(a, (size + a - 1) / a * a + a);
    std::lock_guard<std::mutex> lock(heap.mutex);
    heap.live[p] = size;
    return p;
}
void heap_release(void* user, void* memory, size_t, size_t) {
    LifetimesHeap& heap = *static_cast<LifetimesHeap*>(user);
    {
        std::lock_guard<std::mutex> lock(heap.mutex);
        heap.live.erase(memory);
    }
    std::free(memory);
}

// Callbacks that allocate from `heap` and count its blocks.
ent_callbacks allocating_from(LifetimesHeap& heap) {
    ent_callbacks callbacks;
    ent_callbacks_default(&callbacks);
    callbacks.allocate = heap_allocate;
    callbacks.release = heap_release;
    callbacks.user_data = &heap;
    return callbacks;
}

TEST(Lifetimes, TheScenesMemoryGoesWithTheLastOfTheSceneAndItsSkins) {
    LifetimesHeap heap;
    const ent_callbacks callbacks = allocating_from(heap);
    ent_scene_desc desc = falling_desc();
    desc.callbacks = &callbacks;
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    LifetimesSkinPtr skin = lifetimes_make_skin(scene, ENT_SKIN_TUBE);
    ASSERT_TRUE(step_n(scene, 1e-3, 10));
    const std::size_t with_scene = heap.live.size();
    ent_scene_destroy(scene);
    EXPECT_LT(heap.live.size(), with_scene) << "the simulation is freed at once";
    EXPECT_FALSE(heap.live.empty()) << "the snapshots stay for the skin";
    ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
    skin.reset();
    EXPECT_TRUE(heap.live.empty()) << heap.live.size() << " blocks left after the last skin";
}

TEST(Lifetimes, ADestroyedSceneThatItsSkinsKeepIsRefusedNotRead) {
    ent_scene* scene = nullptr;
    const ent_scene_desc desc = falling_desc();
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    LifetimesSkinPtr skin = lifetimes_make_skin(scene, ENT_SKIN_TUBE);
    ent_scene_destroy(scene);
    // Using a destroyed scene is the caller's mistake; while its skins keep the handle, the
    // library can tell, and says so instead of reading what is gone.
    double axis[6];
    EXPECT_EQ(ent_scene_axis(scene, 2, axis), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(ent_last_error()).find("destroyed"), std::string::npos) << ent_last_error();
    EXPECT_EQ(ent_scene_step(scene, 1e-3), ENT_ERROR_INVALID_ARGUMENT);
    ent_skin* another = nullptr;
    ent_skin_desc skin_desc;
    ent_skin_desc_default(&skin_desc);
    EXPECT_EQ(ent_skin_create(scene, &skin_desc, &another), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(another, nullptr);
}

TEST(Lifetimes, ASceneDestroyedWhileARenderThreadUpdatesItsSkinIsSafe) {
    // The render thread owns the skin and updates it in a loop; the main thread steps and then
    // destroys the scene under it. No call of the skin may fail or read freed memory.
    ent_scene* scene = nullptr;
    const ent_scene_desc desc = falling_desc();
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    LifetimesSkinPtr skin = lifetimes_make_skin(scene, ENT_SKIN_CONVOLUTION);
    std::atomic<bool> destroyed{false}, done{false};
    std::atomic<long> failures{0}, updates_after{0};
    std::thread render([&] {
        while (!done.load()) {
            const bool after = destroyed.load();
            if (ent_skin_update(skin.get()) != ENT_OK) ++failures;
            if (after) ++updates_after;
        }
    });
    ASSERT_TRUE(step_n(scene, 1e-3, 100));
    ent_scene_destroy(scene);
    destroyed = true;
    while (updates_after.load() < 5) std::this_thread::yield();
    done = true;
    render.join();
    EXPECT_EQ(failures.load(), 0);
}

// Issue 27 ("Also"): a destroy that races with a call already in flight on another thread
// lets that call finish, and the memory goes as it returns. The scene's log callback holds
// a step inside the call (max_speed is tiny, so the guard rejects the first attempt and
// logs) while the main thread destroys the scene; then the step goes on and returns a
// status. Before, the destroy freed the scene under the step (ASan: heap-use-after-free).
struct HeldStep : LifetimesHeap {
    std::condition_variable changed;
    bool holding = false, destroyed = false;
};
void hold_the_first_warning(void* user, int32_t level, const char*) {
    HeldStep& held = static_cast<HeldStep&>(*static_cast<LifetimesHeap*>(user));
    if (level != ENT_LOG_WARNING) return;
    std::unique_lock<std::mutex> lock(held.mutex);
    if (held.destroyed || held.holding) return;
    held.holding = true;
    held.changed.notify_all();
    held.changed.wait(lock, [&] { return held.destroyed; });
}
std::size_t live_blocks(LifetimesHeap& heap) {
    std::lock_guard<std::mutex> lock(heap.mutex);
    return heap.live.size();
}

TEST(Lifetimes, ADestroyDuringAStepOnAnotherThreadLeavesTheSceneToTheStep) {
    HeldStep held;
    ent_callbacks callbacks = allocating_from(held);
    callbacks.log = hold_the_first_warning;
    ent_scene_desc desc = falling_desc();
    desc.max_speed_m_per_s = 1e-6;
    desc.callbacks = &callbacks;
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    ent_status stepped = ENT_ERROR_INTERNAL;
    std::string message;
    std::thread stepper([&] {
        stepped = ent_scene_step(scene, 1e-3);
        message = ent_last_error();
    });
    {
        std::unique_lock<std::mutex> lock(held.mutex);
        held.changed.wait(lock, [&] { return held.holding; });
    }
    ent_scene_destroy(scene);  // never waits: the step in flight has the scene
    EXPECT_GT(live_blocks(held), 0u) << "the scene was freed under the step in flight";
    {
        std::lock_guard<std::mutex> lock(held.mutex);
        held.destroyed = true;
    }
    held.changed.notify_all();
    stepper.join();
    EXPECT_EQ(stepped, ENT_ERROR_UNSTABLE) << message;  // the guard's verdict, as without the destroy
    EXPECT_EQ(live_blocks(held), 0u) << "the last call in flight releases the scene's memory";
}

// The same for a skin: the main thread asks for the mesh while another thread updates the
// skin; ENT_ERROR_BUSY says the update is in flight, and the skin is destroyed at once. The
// update finishes on memory that is still there and returns ENT_OK. Before, the destroy
// freed the buffers under it (glibc: "free(): corrupted unsorted chunks").
TEST(Lifetimes, ASkinDestroyedDuringItsUpdateOnAnotherThreadGoesAsTheUpdateReturns) {
    ScenePtr scene = create(falling_desc());
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 20));
    int raced = 0;
    for (int round = 0; round < 40 && raced < 8; ++round) {
        ent_skin* skin = lifetimes_make_skin(scene.get(), round % 2 ? ENT_SKIN_CONVOLUTION : ENT_SKIN_POINT_SKELETON).release();
        std::atomic<bool> finished{false};
        ent_status updated = ENT_ERROR_INTERNAL;
        std::thread render([&] {
            do updated = ent_skin_update(skin);
            while (updated == ENT_ERROR_BUSY);  // refused while the main thread's ent_skin_mesh ran
            finished = true;
        });
        bool destroyed = false;
        while (!finished.load() && !destroyed) {
            ent_mesh_view view;
            std::memset(&view, 0, sizeof view);
            view.struct_size = sizeof view;
            const ent_status status = ent_skin_mesh(skin, &view);
            if (status == ENT_ERROR_BUSY) {
                EXPECT_NE(std::string(ent_last_error()).find("one thread at a time"), std::string::npos)
                    << ent_last_error();
                ent_skin_destroy(skin);
                destroyed = true;
            } else {
                EXPECT_EQ(status, ENT_OK) << ent_last_error();
            }
        }
        render.join();
        if (!destroyed) ent_skin_destroy(skin);
        raced += destroyed ? 1 : 0;
        EXPECT_EQ(updated, ENT_OK);
    }
    EXPECT_GT(raced, 0) << "no update was ever seen in flight (refused as busy)";
}

}  // namespace
