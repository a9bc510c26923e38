// SPDX-License-Identifier: Apache-2.0
// The skins on the two settled piles of the skin benchmark (bench/skin_piles.h): the
// demo's gently folded bowel, and the tight-fold pile where more than half of the axis
// bends with a radius under 4 R and U-turns come down to about 1.5 R. Both implicit skins
// stay within 1 % RMS of the ideal tube of radius R (ent_skin_metrics) on both, away from
// contacts; where the settled folds press into each other the convolution's surfaces meet
// (no overlap beyond the facets, the volume kept); no ring skin folds over, at any
// resolution.
#include "skin_test_support.h"

#include <cmath>

#include "../../bench/skin_piles.h"

using namespace capi_test;
using namespace skin_test;

namespace {

constexpr double kSkinPilesR = 0.0125;


struct ent_skin_metrics measured(ent_scene* scene, int32_t method, double ring_spacing_radii = 0.5,
                                 uint32_t segments = 16) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    desc.method = method;
    desc.ring_spacing_radii = ring_spacing_radii;
    desc.segments = segments;
    SkinPtr skin = make_skin(scene, desc);
    EXPECT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
    const struct ent_skin_metrics m = metrics(skin.get());
    EXPECT_EQ(m.watertight, 1) << "method " << method;
    return m;
}

TEST(SkinPiles, ImplicitSkinsWithinOnePercentOnTheDemoPileAndTheTightFoldPile) {
    for (const enteron::bench::SkinPile& pile : enteron::bench::kSkinPiles) {
        SCOPED_TRACE(pile.name);
        ScenePtr scene(enteron::bench::settle_pile(pile));
        ASSERT_TRUE(scene) << ent_last_error();
        const enteron::bench::BendRadii bends = enteron::bench::bend_radii(scene.get(), kSkinPilesR);
        if (pile.name == std::string("tight_fold_pile")) {
            // What makes the pile tight: at least half the axis under 4 R, and U-turns
            // down to 1.5 R.
            EXPECT_GE(bends.fraction_under[3], 0.5);
            EXPECT_LE(bends.tightest_u_turn, 1.5);
        }
        for (int32_t method : {ENT_SKIN_POINT_SKELETON, ENT_SKIN_CONVOLUTION}) {
            const struct ent_skin_metrics m = measured(scene.get(), method);
            EXPECT_LE(m.free_radius_error_rms, 0.01) << "method " << method;
            EXPECT_GT(m.free_vertex_count, m.vertex_count / 5) << "method " << method;
            // The settled folds press up to 0.09 R into each other (their tubes overlap: the
            // skins meet half-way, inside each other's tube by half that); the volume stays
            // within a percent of the tube's.
            EXPECT_GT(m.tube_overlap_depth_max, 0.02) << "method " << method;
            EXPECT_LT(std::fabs(m.shape_volume_error), 0.01) << "method " << method;
        }
        // The default skin's surfaces meet instead of passing through each other, to the
        // facets' sag where a contact's rim crosses the rings (16 around, R / 2 apart): no
        // overlap area a hundredth of R deep at all, none deeper than 0.04 R; without
        // contact surfaces they pass through each other by about the pressing.
        const struct ent_skin_metrics contacts = measured(scene.get(), ENT_SKIN_CONVOLUTION);
        EXPECT_LT(contacts.overlap_depth_max, 0.04);
        EXPECT_EQ(contacts.overlap_area_m2, 0.0);
        EXPECT_LT(contacts.contact_gap_max, 0.1);
        EXPECT_GT(measured(scene.get(), ENT_SKIN_TUBE).overlap_depth_max, 0.05);
    }
}

TEST(SkinPiles, RingSkinsDoNotFoldOverOnTheTightFoldPileAtAnyResolution) {
    // The pile's smallest radius of curvature is 0.5 R: a ring of radius R there would
    // reach past its neighbours on the inner side.
    const enteron::bench::SkinPile& pile = enteron::bench::kTightFoldPile;
    ScenePtr scene(enteron::bench::settle_pile(pile));
    ASSERT_TRUE(scene) << ent_last_error();
    const struct { double ring_spacing; uint32_t segments; } resolutions[] = {{1.0, 8}, {0.5, 16}, {0.25, 32}};
    for (int32_t method : {ENT_SKIN_TUBE, ENT_SKIN_CONVOLUTION})
        for (const auto& resolution : resolutions) {
            const struct ent_skin_metrics m = measured(scene.get(), method, resolution.ring_spacing, resolution.segments);
            EXPECT_EQ(m.inverted_triangles, 0u) << "method " << method << ", rings " << resolution.ring_spacing << " R";
        }
}

}  // namespace
