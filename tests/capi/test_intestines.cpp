// SPDX-License-Identifier: Apache-2.0
// The intestines of a scene (ent_scene_intestine_count, ent_scene_intestine_axis): a scene
// of one intestine has one, and its axis is ent_scene_axis's to the bit, at every published
// state, for any sample count.
#include "capi_test_support.h"

using namespace capi_test;

namespace {

TEST(Intestines, AOneIntestineSceneHasOneWhoseAxisIsTheScenesAxis) {
    ent_scene_desc desc = default_desc();
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
    const ScenePtr scene = create(desc);
    int32_t count = -1;
    ASSERT_EQ(ent_scene_intestine_count(scene.get(), &count), ENT_OK) << ent_last_error();
    EXPECT_EQ(count, 1);
    for (int step = 0; step < 3; ++step) {
        for (const uint32_t samples : {2u, 7u, 100u}) {
            std::vector<double> axis(3 * samples, 0.0), intestine(3 * samples, 1.0);
            ASSERT_EQ(ent_scene_axis(scene.get(), samples, axis.data()), ENT_OK) << ent_last_error();
            ASSERT_EQ(ent_scene_intestine_axis(scene.get(), 0, samples, intestine.data()), ENT_OK) << ent_last_error();
            EXPECT_EQ(intestine, axis) << samples << " samples after " << step << " steps";
        }
        ASSERT_EQ(ent_scene_step(scene.get(), 0.01), ENT_OK) << ent_last_error();
    }
    // The count stays (the layout is the scene's for its life).
    ASSERT_EQ(ent_scene_intestine_count(scene.get(), &count), ENT_OK);
    EXPECT_EQ(count, 1);
}

}  // namespace
