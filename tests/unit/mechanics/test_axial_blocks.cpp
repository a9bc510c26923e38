// SPDX-License-Identifier: Apache-2.0
// The shared axial blocks (lib/mechanics/axial_blocks.h): the stretch and the axial damper
// adding their blocks into one set equal each adding its own.
#include "mechanics/axial_blocks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/damping_force.h"
#include "mechanics/effect_checks.h"
#include "mechanics/state.h"
#include "mechanics/stretch_force.h"
#include "mechanics/system_matrix.h"

namespace {

using namespace mechanics_test;

TEST(AxialBlocks, SharedBlocksOfStretchAndDampingEqualEachAddingItsOwn) {
    // The implicit integrator lets the stretch and the axial damper sum their blocks per
    // node and adds them once; the result must be the two linearisations added apart, in
    // either order of the laws (the first one gives the tangent).
    const mech::DampingCoefficients coefficients{0.05, 0.05, 1e-3};
    mech::StretchForce stretch(model(), 100.0, std::pmr::get_default_resource());
    mech::DampingForce damping(model(), coefficients, std::pmr::get_default_resource());
    const mech::State s = stretched_state(41);
    const double h = 1e-3;
    mech::SystemMatrix apart;
    apart.resize(3 * kPoints);
    std::vector<double> force_apart(3 * kPoints, 0.0), hv_apart(3 * kPoints, 0.0);
    mech::Linearization own{&apart, h, hv_apart.data()};
    stretch.evaluate(s, force_apart.data(), &own);
    damping.evaluate(s, force_apart.data(), &own);
    // One set of blocks through every round, as in the integrator: a round forgets the last.
    mech::AxialBlocks blocks(model(), std::pmr::get_default_resource());
    for (const bool stretch_first : {true, false}) {
        mech::SystemMatrix shared;
        shared.resize(3 * kPoints);
        std::vector<double> force(3 * kPoints, 0.0), hv(3 * kPoints, 0.0);
        blocks.clear();
        mech::Linearization lin{&shared, h, hv.data(), &blocks};
        mech::Effect* order[2] = {&stretch, &damping};
        if (!stretch_first) std::swap(order[0], order[1]);
        for (mech::Effect* effect : order) effect->evaluate(s, force.data(), &lin);
        // Nothing reaches the system until the integrator adds the blocks.
        EXPECT_EQ(shared.at(0, 0), 0.0);
        blocks.add_to(shared);
        double scale = 0.0;
        for (std::size_t i = 0; i < 3 * kPoints; ++i)
            for (std::size_t j = 0; j < 3 * kPoints; ++j) scale = std::max(scale, std::fabs(apart.at(i, j)));
        ASSERT_GT(scale, 0.0);
        for (std::size_t i = 0; i < 3 * kPoints; ++i) {
            for (std::size_t j = 0; j < 3 * kPoints; ++j)
                EXPECT_NEAR(shared.at(i, j), apart.at(i, j), 1e-12 * scale) << "(" << i << ", " << j << ")";
            // The forces too, up to the order of the two laws' sums.
            EXPECT_NEAR(force[i], force_apart[i], 1e-12 * (1.0 + std::fabs(force_apart[i])));
            EXPECT_NEAR(hv[i], hv_apart[i], 1e-12 * (1.0 + std::fabs(hv_apart[i])));
        }
    }
    // A last round with the damper alone, at another state: nothing of the stretch's blocks
    // (nor of their tangents) may stay.
    const mech::State other = stretched_state(42);
    mech::SystemMatrix alone, shared;
    alone.resize(3 * kPoints);
    shared.resize(3 * kPoints);
    std::vector<double> f(3 * kPoints, 0.0), hv(3 * kPoints, 0.0);
    mech::Linearization direct{&alone, h, hv.data()};
    damping.evaluate(other, f.data(), &direct);
    blocks.clear();
    mech::Linearization lin{&shared, h, hv.data(), &blocks};
    damping.evaluate(other, f.data(), &lin);
    blocks.add_to(shared);
    double scale = 0.0;
    for (std::size_t i = 0; i < 3 * kPoints; ++i)
        for (std::size_t j = 0; j < 3 * kPoints; ++j) scale = std::max(scale, std::fabs(alone.at(i, j)));
    ASSERT_GT(scale, 0.0);
    for (std::size_t i = 0; i < 3 * kPoints; ++i)
        for (std::size_t j = 0; j < 3 * kPoints; ++j)
            EXPECT_NEAR(shared.at(i, j), alone.at(i, j), 1e-12 * scale) << "(" << i << ", " << j << ")";
}

}  // namespace
