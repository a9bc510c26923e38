// SPDX-License-Identifier: Apache-2.0
// The skins on the two settled piles of the skin benchmark (bench/skin_piles.h): the
// demo's gently folded bowel, and the tight-fold pile where more than half of the axis
// bends with a radius under 4 R and U-turns come down to about 1.5 R. Both implicit skins
// stay within 1 % RMS of the ideal tube of radius R (ent_skin_metrics) on both.
#include "skin_test_support.h"

#include "../../bench/skin_piles.h"

using namespace capi_test;
using namespace skin_test;

namespace {

constexpr double kR = 0.0125;


double radius_error_rms(ent_scene* scene, int32_t method) {
    SkinPtr skin = make_skin(scene, method);
    EXPECT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
    const struct ent_skin_metrics m = metrics(skin.get());
    EXPECT_EQ(m.watertight, 1) << "method " << method;
    return m.radius_error_rms;
}

TEST(SkinPiles, ImplicitSkinsWithinOnePercentOnTheDemoPileAndTheTightFoldPile) {
    for (const enteron::bench::SkinPile& pile : enteron::bench::kSkinPiles) {
        SCOPED_TRACE(pile.name);
        ScenePtr scene(enteron::bench::settle_pile(pile));
        ASSERT_TRUE(scene) << ent_last_error();
        const enteron::bench::BendRadii bends = enteron::bench::bend_radii(scene.get(), kR);
        if (pile.name == std::string("tight_fold_pile")) {
            // What makes the pile tight: at least half the axis under 4 R, and U-turns
            // down to 1.5 R.
            EXPECT_GE(bends.fraction_under[3], 0.5);
            EXPECT_LE(bends.tightest_u_turn, 1.5);
        }
        for (int32_t method : {ENT_SKIN_POINT_SKELETON, ENT_SKIN_CONVOLUTION}) {
            const double rms = radius_error_rms(scene.get(), method);
            EXPECT_LE(rms, 0.01) << "method " << method;
        }
    }
}

}  // namespace
