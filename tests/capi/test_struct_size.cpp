// SPDX-License-Identifier: Apache-2.0
// The struct_size handshake from the library's side: the _init functions behind the
// _default macros write exactly the size they are given, every released size is served,
// and sizes no release has are refused with ENT_ERROR_VERSION and nothing written.
// (tests/abi/old_caller.c does the same from a program built against an older header.)
#include "capi_test_support.h"
#include "test_helpers.h"

#include <cstddef>

using namespace capi_test;

namespace {

// The released sizes: the 0.0 preview (a simulated release, tests/abi/enteron_v0_0.h)
// lacked ent_scene_desc.callbacks and ent_stats.last_step_ns.
constexpr uint32_t kOldDescSize = offsetof(ent_scene_desc, callbacks);
constexpr uint32_t kOldStatsSize = offsetof(ent_stats, last_step_ns);
// 0.1: ent_stats up to last_step_ns, before what a slow step did.
constexpr uint32_t kStatsSize01 = offsetof(ent_stats, last_step_attempts);

using enteron_test::contains;

bool all_bytes(const void* memory, std::size_t from, std::size_t to, unsigned char value) {
    const auto* bytes = static_cast<const unsigned char*>(memory);
    for (std::size_t i = from; i < to; ++i)
        if (bytes[i] != value) return false;
    return true;
}

TEST(StructSize, DescInitWritesExactlyTheSizeItIsGiven) {
    ent_scene_desc full;
    ent_scene_desc_default(&full);
    for (uint32_t size : {kOldDescSize, uint32_t(sizeof(ent_scene_desc))}) {
        SCOPED_TRACE(size);
        ent_scene_desc desc;
        std::memset(&desc, 0xcd, sizeof desc);
        ASSERT_EQ(ent_scene_desc_init(&desc, size), ENT_OK) << ent_last_error();
        EXPECT_EQ(desc.struct_size, size);
        // The bytes up to size are the defaults (struct_size aside), the rest untouched.
        EXPECT_EQ(std::memcmp(reinterpret_cast<char*>(&desc) + sizeof desc.struct_size,
                              reinterpret_cast<char*>(&full) + sizeof full.struct_size,
                              size - sizeof desc.struct_size),
                  0);
        EXPECT_TRUE(all_bytes(&desc, size, sizeof desc, 0xcd));
    }
}

TEST(StructSize, UnknownSizesAreRefusedAndNothingIsWritten) {
    for (uint32_t size : {0u, 4u, kOldDescSize - 8, kOldDescSize + 4, uint32_t(sizeof(ent_scene_desc) + 8),
                          0xffffffffu}) {
        SCOPED_TRACE(size);
        ent_scene_desc desc;
        std::memset(&desc, 0xcd, sizeof desc);
        EXPECT_EQ(ent_scene_desc_init(&desc, size), ENT_ERROR_VERSION);
        EXPECT_TRUE(contains(ent_last_error(), "ent_scene_desc.struct_size is " + std::to_string(size)))
            << ent_last_error();
        EXPECT_TRUE(all_bytes(&desc, 0, sizeof desc, 0xcd));
    }
    for (uint32_t size : {0u, uint32_t(sizeof(ent_callbacks) - 8), uint32_t(sizeof(ent_callbacks) + 8)}) {
        SCOPED_TRACE(size);
        ent_callbacks callbacks;
        std::memset(&callbacks, 0xcd, sizeof callbacks);
        EXPECT_EQ(ent_callbacks_init(&callbacks, size), ENT_ERROR_VERSION);
        EXPECT_TRUE(contains(ent_last_error(), "ent_callbacks.struct_size")) << ent_last_error();
        EXPECT_TRUE(all_bytes(&callbacks, 0, sizeof callbacks, 0xcd));
    }
    EXPECT_EQ(ent_scene_desc_init(nullptr, sizeof(ent_scene_desc)), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_callbacks_init(nullptr, sizeof(ent_callbacks)), ENT_ERROR_INVALID_ARGUMENT);
}

TEST(StructSize, AnOldDescriptionGetsTheDefaultsOfTheFieldsItLacks) {
    // What lies past an old caller's struct is not the caller's: here a bogus callbacks
    // pointer, which the library must never read (it would crash on it).
    ent_scene_desc desc = default_desc();
    desc.control_points = 12;
    desc.length_m = 0.5;
    desc.struct_size = kOldDescSize;
    desc.callbacks = reinterpret_cast<const ent_callbacks*>(uintptr_t{0x10});
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create(&desc, &scene), ENT_OK) << ent_last_error();
    ScenePtr owned(scene);
    ASSERT_TRUE(step_n(scene, 1e-3, 5));
    EXPECT_EQ(stats(scene).control_points, 12u);
}

// ent_scene_stats into a struct of an older `size`, its bytes marked 0xcd beforehand.
ent_stats stats_of_size(const ent_scene* scene, uint32_t size) {
    ent_stats out;
    std::memset(&out, 0xcd, sizeof out);
    out.struct_size = size;
    EXPECT_EQ(ent_scene_stats(scene, &out), ENT_OK) << ent_last_error();
    return out;
}

TEST(StructSize, OldStatsAreFilledUpToTheirSizeOnly) {
    ScenePtr scene = create(default_desc());
    ASSERT_TRUE(scene);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 3));
    const ent_stats full = stats(scene.get());
    const ent_stats old = stats_of_size(scene.get(), kOldStatsSize);
    EXPECT_EQ(old.steps, 3u);
    EXPECT_EQ(old.time_s, full.time_s);
    EXPECT_EQ(old.kinetic_energy_J, full.kinetic_energy_J);
    EXPECT_TRUE(all_bytes(&old, kOldStatsSize, sizeof old, 0xcd)) << "last_step_ns was written";

    const ent_stats v01 = stats_of_size(scene.get(), kStatsSize01);
    EXPECT_EQ(v01.steps, 3u);
    EXPECT_EQ(v01.last_step_ns, full.last_step_ns);
    EXPECT_TRUE(all_bytes(&v01, kStatsSize01, sizeof v01, 0xcd)) << "written past last_step_ns";
    EXPECT_EQ(full.last_step_attempts, 1u) << "the current size gets them";
}

// ent_skin_desc and ent_skin_metrics before the level of detail and the facet error.
constexpr uint32_t kOldSkinDescSize = offsetof(ent_skin_desc, ring_chord_error_radii);
constexpr uint32_t kOldSkinMetricsSize = offsetof(struct ent_skin_metrics, facet_error_rms);

TEST(StructSize, OldSkinDescriptionsAreServedWithEvenRings) {
    ent_skin_desc full;
    ent_skin_desc_default(&full);
    EXPECT_EQ(full.ring_chord_error_radii, 0.0);
    ent_skin_desc old;
    std::memset(&old, 0xcd, sizeof old);
    ASSERT_EQ(ent_skin_desc_init(&old, kOldSkinDescSize), ENT_OK) << ent_last_error();
    EXPECT_TRUE(all_bytes(&old, kOldSkinDescSize, sizeof old, 0xcd)) << "written past the old size";
    EXPECT_EQ(old.segments, full.segments);
    // What lies past the old struct (0xcd bytes: a huge negative double, out of range) is
    // not read: the skin is made with the default, even rings.
    ScenePtr scene = create(default_desc());
    ent_skin* skin = nullptr;
    ASSERT_EQ(ent_skin_create(scene.get(), &old, &skin), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_skin_update(skin), ENT_OK) << ent_last_error();
    struct ent_skin_metrics m;
    std::memset(&m, 0xcd, sizeof m);
    m.struct_size = kOldSkinMetricsSize;
    EXPECT_EQ(ent_skin_metrics(skin, &m), ENT_OK) << ent_last_error();
    EXPECT_GT(m.triangle_count, 0u);
    EXPECT_TRUE(all_bytes(&m, kOldSkinMetricsSize, sizeof m, 0xcd)) << "facet errors written past the old size";
    ent_skin_destroy(skin);
    // The current size refuses that value by name.
    full.ring_chord_error_radii = -1.0;
    EXPECT_EQ(ent_skin_create(scene.get(), &full, &skin), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_TRUE(contains(ent_last_error(), "ring_chord_error_radii")) << ent_last_error();
}

// ent_skin_desc before contact surfaces and the curvature-following skeleton, and
// ent_skin_metrics before the contact and motion measures.
constexpr uint32_t kPreContactSkinDescSize = offsetof(ent_skin_desc, contact_surfaces);
constexpr uint32_t kPreContactSkinMetricsSize = offsetof(struct ent_skin_metrics, overlap_depth_max);

TEST(StructSize, SkinDescriptionsFromBeforeContactsGetTheirDefaults) {
    ent_skin_desc full;
    ent_skin_desc_default(&full);
    EXPECT_EQ(full.contact_surfaces, 1);
    EXPECT_EQ(full.skeleton_chord_error_radii, 0.0);
    ent_skin_desc old;
    std::memset(&old, 0xcd, sizeof old);
    ASSERT_EQ(ent_skin_desc_init(&old, kPreContactSkinDescSize), ENT_OK) << ent_last_error();
    EXPECT_TRUE(all_bytes(&old, kPreContactSkinDescSize, sizeof old, 0xcd)) << "written past the old size";
    // What lies past the old struct (0xcd: out of range for both fields) is not read.
    ScenePtr scene = create(default_desc());
    ent_skin* skin = nullptr;
    ASSERT_EQ(ent_skin_create(scene.get(), &old, &skin), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_skin_update(skin), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_skin_update(skin), ENT_OK) << ent_last_error();
    struct ent_skin_metrics m;
    std::memset(&m, 0xcd, sizeof m);
    m.struct_size = kPreContactSkinMetricsSize;
    EXPECT_EQ(ent_skin_metrics(skin, &m), ENT_OK) << ent_last_error();
    EXPECT_GT(m.triangle_count, 0u);
    EXPECT_TRUE(all_bytes(&m, kPreContactSkinMetricsSize, sizeof m, 0xcd)) << "contact measures written past the old size";
    // The current size: the motion measures compare with the update before.
    m.struct_size = sizeof m;
    EXPECT_EQ(ent_skin_metrics(skin, &m), ENT_OK) << ent_last_error();
    EXPECT_EQ(m.has_previous_update, 1);
    EXPECT_LT(m.vertex_excess_motion_max, 1e-6);  // the same state twice
    ent_skin_destroy(skin);
}

// ent_tool_feedback before `saturated` (issue 27): served, nothing written past it; a size
// between two released ones is refused.
TEST(StructSize, ToolFeedbackBeforeSaturatedIsServed) {
    ScenePtr scene = create(default_desc());
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    ASSERT_EQ(ent_tool_add(scene.get(), &tool, nullptr), ENT_OK) << ent_last_error();
    constexpr uint32_t kBeforeSaturated = offsetof(ent_tool_feedback, saturated);
    ent_tool_feedback old;
    std::memset(&old, 0xcd, sizeof old);
    old.struct_size = kBeforeSaturated;
    ASSERT_EQ(ent_tool_read_feedback(scene.get(), 0, &old), ENT_OK) << ent_last_error();
    EXPECT_TRUE(all_bytes(&old, kBeforeSaturated, sizeof old, 0xcd)) << "written past the old size";
    EXPECT_EQ(old.steps, 0u);
    ent_tool_feedback between;
    std::memset(&between, 0xcd, sizeof between);
    between.struct_size = kBeforeSaturated + 2;
    EXPECT_EQ(ent_tool_read_feedback(scene.get(), 0, &between), ENT_ERROR_VERSION);
    EXPECT_TRUE(contains(ent_last_error(), "ent_tool_feedback.struct_size")) << ent_last_error();
}

}  // namespace
