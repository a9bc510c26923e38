// SPDX-License-Identifier: Apache-2.0
// Allocator and log callbacks (ent_callbacks): every allocation is released with the size and
// alignment it was made with, nothing is allocated by steps after the first, an allocator that
// fails gives ENT_ERROR_OUT_OF_MEMORY without leaking, and the hooks get their user_data.
#include "capi_test_support.h"

#include <cstdlib>
#include <map>
#include <mutex>

using namespace capi_test;

namespace {

struct Heap {
    struct Block {
        size_t size;
        size_t alignment;
    };
    std::mutex mutex;
    std::map<void*, Block> live;
    uint64_t allocations = 0;
    uint64_t releases = 0;
    uint64_t mismatched_releases = 0;
    uint64_t bad_alignments = 0;
    // Fail every allocation from this one on (0-based); -1: never fail.
    long fail_from = -1;
    void* expected_user_data = nullptr;
    uint64_t wrong_user_data = 0;
};

void* allocate(void* user, size_t size, size_t alignment) {
    Heap& heap = *static_cast<Heap*>(user);
    std::lock_guard<std::mutex> lock(heap.mutex);
    if (user != heap.expected_user_data) ++heap.wrong_user_data;
    if (alignment == 0 || (alignment & (alignment - 1)) != 0) ++heap.bad_alignments;
    if (heap.fail_from >= 0 && heap.allocations >= uint64_t(heap.fail_from)) {
        ++heap.allocations;
        return nullptr;
    }
    ++heap.allocations;
    const size_t a = alignment < sizeof(void*) ? sizeof(void*) : alignment;
    void* p = std::aligned_alloc(a, (size + a - 1) / a * a + a);  // never size 0
    if (p != nullptr) heap.live[p] = {size, alignment};
    return p;
}

void release(void* user, void* memory, size_t size, size_t alignment) {
    Heap& heap = *static_cast<Heap*>(user);
    std::lock_guard<std::mutex> lock(heap.mutex);
    if (user != heap.expected_user_data) ++heap.wrong_user_data;
    ++heap.releases;
    const auto it = heap.live.find(memory);
    if (it == heap.live.end() || it->second.size != size || it->second.alignment != alignment) {
        ++heap.mismatched_releases;
        return;  // not ours or described wrongly: do not free what we cannot vouch for
    }
    heap.live.erase(it);
    std::free(memory);
}

ent_callbacks callbacks_for(Heap& heap) {
    ent_callbacks c;
    ent_callbacks_default(&c);
    c.allocate = allocate;
    c.release = release;
    c.user_data = &heap;
    heap.expected_user_data = &heap;
    return c;
}

ent_scene_desc busy_desc(const ent_callbacks* callbacks, int32_t integrator) {
    ent_scene_desc desc = default_desc();
    desc.control_points = 40;
    desc.length_m = 1.0;
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.mesentery_attachments = 10;
    desc.pinned_ends = ENT_PIN_BOTH;
    desc.integrator = integrator;
    desc.callbacks = callbacks;
    return desc;
}

TEST(Callbacks, EveryAllocationIsReleasedAsItWasMadeAndStepsAllocateNothing) {
    for (int32_t integrator : kIntegrators) {
        SCOPED_TRACE(integrator_name(integrator));
        Heap heap;
        const ent_callbacks callbacks = callbacks_for(heap);
        const ent_scene_desc desc = busy_desc(&callbacks, integrator);
        ent_scene* scene = nullptr;
        ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
        EXPECT_GT(heap.allocations, 0u) << "the scene must use the caller's allocator";
        ASSERT_EQ(ent_scene_step(scene, 1e-3), ENT_OK) << ent_last_error();
        const uint64_t after_first = heap.allocations;
        for (int i = 0; i < 50; ++i) ASSERT_EQ(ent_scene_step(scene, 1e-3), ENT_OK) << ent_last_error();
        EXPECT_EQ(heap.allocations, after_first) << "steps after the first allocated";
        ent_scene_destroy(scene);
        EXPECT_TRUE(heap.live.empty()) << heap.live.size() << " blocks leaked";
        EXPECT_EQ(heap.mismatched_releases, 0u);
        EXPECT_EQ(heap.bad_alignments, 0u);
        EXPECT_EQ(heap.wrong_user_data, 0u);
        EXPECT_EQ(heap.allocations, heap.releases);
    }
}

TEST(Callbacks, JsonScenesUseTheCallbacksToo) {
    Heap heap;
    const ent_callbacks callbacks = callbacks_for(heap);
    const std::string json = R"({"intestine": {"length": 1.0, "control_points": 30, "stretch_stiffness": 100,
                                                "bend_stiffness": 0.0025},
                                 "gravity": [0, 0, -9.81], "damping": {}})";
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create_json_with(json.data(), json.size(), &callbacks, &scene), ENT_OK) << ent_last_error();
    EXPECT_GT(heap.allocations, 0u);
    ASSERT_TRUE(step_n(scene, 1e-3, 10));
    ent_scene_destroy(scene);
    EXPECT_TRUE(heap.live.empty());
    EXPECT_EQ(heap.mismatched_releases, 0u);
}

TEST(Callbacks, AFailingAllocatorGivesOutOfMemoryAndLeaksNothing) {
    // Fail the k-th allocation for every k until creation succeeds: every partial
    // construction must be unwound through `release`.
    Heap probe;
    {
        const ent_callbacks callbacks = callbacks_for(probe);
        const ent_scene_desc desc = busy_desc(&callbacks, ENT_INTEGRATOR_IMPLICIT_EULER);
        ent_scene* scene = nullptr;
        ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
        ent_scene_destroy(scene);
    }
    const long needed = long(probe.allocations);
    ASSERT_GT(needed, 0);
    for (long k = 0; k < needed; ++k) {
        SCOPED_TRACE("failing allocation " + std::to_string(k) + " of " + std::to_string(needed));
        Heap heap;
        heap.fail_from = k;
        const ent_callbacks callbacks = callbacks_for(heap);
        const ent_scene_desc desc = busy_desc(&callbacks, ENT_INTEGRATOR_IMPLICIT_EULER);
        char storage;
        ent_scene* out = reinterpret_cast<ent_scene*>(&storage);
        ASSERT_EQ(ent_scene_create(&desc, &out), ENT_ERROR_OUT_OF_MEMORY) << ent_last_error();
        EXPECT_EQ(out, reinterpret_cast<ent_scene*>(&storage));
        EXPECT_TRUE(heap.live.empty()) << heap.live.size() << " blocks leaked";
        EXPECT_EQ(heap.mismatched_releases, 0u);
        if (::testing::Test::HasFailure()) break;
    }
}

struct LogSink {
    std::mutex mutex;
    int lines = 0;
    int bad_levels = 0;
    int null_messages = 0;
};

void log_line(void* user, int32_t level, const char* message) {
    LogSink& sink = *static_cast<LogSink*>(user);
    std::lock_guard<std::mutex> lock(sink.mutex);
    ++sink.lines;
    if (level < ENT_LOG_DEBUG || level > ENT_LOG_ERROR) ++sink.bad_levels;
    if (message == nullptr) ++sink.null_messages;
}

TEST(Callbacks, LogLinesCarryAValidLevelAndMessage) {
    // Whether a scene logs at all is the library's choice; what it logs must be well formed,
    // and a rejected step (see test_unstable.cpp) is worth a line.
    LogSink sink;
    ent_callbacks callbacks;
    ent_callbacks_default(&callbacks);
    callbacks.log = log_line;
    callbacks.user_data = &sink;
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
    desc.control_points = 10;
    desc.length_m = 1.0;
    desc.integrator = ENT_INTEGRATOR_SYMPLECTIC_EULER;
    desc.max_speed_m_per_s = 1e-6;
    desc.callbacks = &callbacks;
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    EXPECT_EQ(ent_scene_step(scene, 1e-3), ENT_ERROR_UNSTABLE);
    ent_scene_destroy(scene);
    EXPECT_GT(sink.lines, 0);
    EXPECT_EQ(sink.bad_levels, 0);
    EXPECT_EQ(sink.null_messages, 0);
}

}  // namespace
