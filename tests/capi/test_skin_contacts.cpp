// SPDX-License-Identifier: Apache-2.0
// Contact surfaces through the C API (ent_skin_desc.contact_surfaces, the contact measures
// of ent_skin_metrics): a fold of a small pile pressed by a tool into the folds beneath.
// The skins' surfaces meet on the contact instead of passing through each other, the
// volume stays, nothing folds over; without contact surfaces the press shows as overlap.
#include "skin_test_support.h"

#include "../../bench/skin_piles.h"

#include <cmath>

using namespace capi_test;
using namespace skin_test;

namespace {


struct ent_skin_metrics skin_of(ent_scene* scene, int32_t method, int32_t contacts) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    EXPECT_EQ(desc.contact_surfaces, 1);  // the default
    desc.method = method;
    desc.contact_surfaces = contacts;
    SkinPtr skin = make_skin(scene, desc);
    EXPECT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
    return metrics(skin.get());
}

TEST(SkinContacts, AFoldPressedByAToolMeetsTheFoldBeneath) {
    // A small pile's highest fold pressed with 8 N by a tool into the folds beneath.
    double tip[3];
    ScenePtr scene(enteron::bench::pressed_small_pile(tip));
    ASSERT_TRUE(scene) << ent_last_error();
    // Pressed: the folds' tubes overlap by far more than when they rest on each other.
    const struct ent_skin_metrics through = skin_of(scene.get(), ENT_SKIN_CONVOLUTION, 0);
    ASSERT_GT(through.tube_overlap_depth_max, 0.15);
    EXPECT_GT(through.overlap_depth_max, 0.1);  // the surfaces pass through each other
    EXPECT_GT(through.overlap_area_m2, 0.0);
    // With contact surfaces (the default) they meet: no overlap beyond the facets' sag, no
    // gap, the volume the same to a fraction of a percent, nothing folded over.
    const struct ent_skin_metrics met = skin_of(scene.get(), ENT_SKIN_CONVOLUTION, 1);
    EXPECT_LT(met.overlap_depth_max, 0.03);
    EXPECT_EQ(met.overlap_area_m2, 0.0);
    EXPECT_LT(met.contact_gap_max, 0.03);
    EXPECT_LT(std::fabs(met.shape_volume_error), 0.003);
    EXPECT_NEAR(met.volume_m3, through.volume_m3, 0.003 * through.volume_m3);
    EXPECT_EQ(met.inverted_triangles, 0u);
    EXPECT_EQ(met.watertight, 1);
    // The point skeleton draws the two legs' union, swollen where they meet.
    const struct ent_skin_metrics point = skin_of(scene.get(), ENT_SKIN_POINT_SKELETON, 1);
    EXPECT_LT(point.overlap_depth_max, 0.03);
    EXPECT_LT(std::fabs(point.shape_volume_error), 0.01);
    EXPECT_EQ(point.watertight, 1);
}

}  // namespace
