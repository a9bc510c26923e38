// SPDX-License-Identifier: Apache-2.0
// Pinned control points (lib/mechanics/pinned_points.h): a pinned point's rows become
// constraints (zero force, identity rows of the implicit system and of the mass matrix, zero
// H v, no border coupling); pins are sorted and unique, made and let go between steps; a
// point attached to a moving frame gets the velocity that takes it to where its frame puts
// it at the end of the step, bounded by half the guard's speed; the work the attached pins
// may do is bounded; a saved state restores the pins, and a damaged one is refused with
// nothing changed.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "base/error.h"
#include "base/saved_image.h"
#include "base/state_io.h"
#include "mechanics/bordered_system.h"
#include "mechanics/pinned_points.h"

namespace enteron::mechanics {
namespace {

constexpr std::size_t kPinnedBowelPoints = 8;
std::pmr::memory_resource* const kMemory = std::pmr::new_delete_resource();

State moving_state() {
    State s;
    s.resize(kPinnedBowelPoints);
    for (std::size_t k = 0; k < s.q.size(); ++k) {
        s.q[k] = 0.1 * double(k);
        s.v[k] = 0.01 * double(k + 1);
    }
    return s;
}

TEST(PinnedPoints, PinnedRowsBecomeConstraints) {
    RigidFrames frames(kMemory);
    PinnedPoints pins({5, 2, 5}, frames, 1.0, kMemory);
    EXPECT_EQ(pins.size(), 2u) << "sorted and unique";
    EXPECT_TRUE(pins.pinned(2));
    EXPECT_FALSE(pins.pinned(3));
    const State state = moving_state();
    std::vector<double> force(3 * kPinnedBowelPoints, 1.0), hv(3 * kPinnedBowelPoints, 2.0);
    SystemMatrix system;
    system.resize(3 * kPinnedBowelPoints);
    for (std::size_t i = 0; i < 3 * kPinnedBowelPoints; ++i)
        for (std::size_t j = i >= 11 ? i - 11 : 0; j <= i; ++j) system.add(i, j, i == j ? 10.0 : 0.5);
    BorderedSystem border(kMemory);
    border.reserve(1, 3 * kPinnedBowelPoints);
    const std::size_t body = border.add_body(Mat3::Identity(), Vec3::Zero());
    border.add_coupling(body, spline::segment_weights(kPinnedBowelPoints, 2, 0.5, spline::Derivative::value), Mat3::Identity());
    const Linearization lin{&system, 1e-3, hv.data(), nullptr, &border};
    pins.evaluate(state, force.data(), &lin);
    for (std::size_t i = 0; i < 3 * kPinnedBowelPoints; ++i) {
        const bool pinned = i / 3 == 2 || i / 3 == 5;
        EXPECT_EQ(force[i], pinned ? 0.0 : 1.0) << i;
        EXPECT_EQ(hv[i], pinned ? 0.0 : 2.0) << i;
        for (std::size_t j = 0; j < 3 * kPinnedBowelPoints && pinned; ++j)
            EXPECT_EQ(system.at(i, j), i == j ? 1.0 : 0.0) << i << ", " << j;
    }
    // The border no longer couples the body to point 2: its solve moves no pinned row.
    ASSERT_TRUE(system.factor());
    std::vector<double> dv(3 * kPinnedBowelPoints, 0.0);
    border.solve(system, dv.data());
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(dv[6 + c], 0.0);
    numerics::ScalarBandMatrix mass;
    mass.resize(kPinnedBowelPoints);
    for (std::size_t i = 0; i < kPinnedBowelPoints; ++i) mass.add(i, i, 3.0);
    pins.constrain(mass);
    EXPECT_EQ(mass.at(5, 5), 1.0);
    EXPECT_EQ(mass.at(4, 4), 3.0);
}

TEST(PinnedPoints, PinsAreMadeAndLetGoBetweenSteps) {
    RigidFrames frames(kMemory);
    PinnedPoints pins({}, frames, 1.0, kMemory);
    State state = moving_state();
    pins.pin(3, PinnedPoints::kWorld, state);
    EXPECT_TRUE(pins.pinned(3));
    EXPECT_EQ(point_at(state.v.data(), 3), Vec3::Zero()) << "held where it is, at rest";
    EXPECT_NE(point_at(state.v.data(), 4), Vec3::Zero());
    pins.pin(3, PinnedPoints::kWorld, state);
    EXPECT_EQ(pins.size(), 1u) << "pinning again re-attaches, it adds nothing";
    EXPECT_TRUE(pins.unpin(3));
    EXPECT_FALSE(pins.unpin(3));
    EXPECT_FALSE(pins.pinned(3));
}

TEST(PinnedPoints, AnAttachedPointFollowsItsFrameAtBoundedSpeed) {
    RigidFrames frames(kMemory);
    const std::size_t frame = frames.add(RigidPose{});
    const double max_speed = 2.0;
    PinnedPoints pins({}, frames, max_speed, kMemory);
    EXPECT_EQ(pins.speed_limit(), 0.5 * max_speed);
    State state = moving_state();
    pins.pin(1, frame, state);
    const Vec3 start = point_at(state.q.data(), 1);
    const double dt = 0.01;
    // The frame moves 5 mm along x in the step: the point gets 0.5 m/s.
    RigidPose moved;
    moved.position = Vec3(0.005, 0.0, 0.0);
    frames.set_target(frame, moved);
    frames.begin_step(0.0, dt);
    EXPECT_TRUE(pins.prescribe(state, dt));
    EXPECT_LT((point_at(state.v.data(), 1) - Vec3(0.5, 0.0, 0.0)).norm(), 1e-12);
    frames.end_step(true);
    // It jumps 1 m: the point follows at the speed limit, towards it.
    moved.position = Vec3(0.0, 1.0, 0.0);
    frames.set_target(frame, moved);
    frames.begin_step(dt, dt);
    point_at(state.q.data(), 1) = start + Vec3(0.005, 0.0, 0.0);
    EXPECT_TRUE(pins.prescribe(state, dt));
    const Vec3 velocity = point_at(state.v.data(), 1);
    EXPECT_NEAR(velocity.norm(), pins.speed_limit(), 1e-12);
    EXPECT_GT(velocity.y(), 0.99 * velocity.norm());
    // The work bound: twice the largest power of the pinned rows' forces, times the step.
    pins.begin_step(dt);
    pins.begin_attempt();
    std::vector<double> force(3 * kPinnedBowelPoints, 0.0);
    point_at(force.data(), 1) = Vec3(0.0, 0.0, 4.0);  // 4 N on the attached point
    pins.evaluate(state, force.data(), nullptr);
    EXPECT_NEAR(pins.external_work_bound(), 2.0 * 4.0 * velocity.norm() * dt, 1e-12);
}

TEST(PinnedPoints, ASavedStateRestoresThePinsAndADamagedOneIsRefused) {
    RigidFrames frames(kMemory);
    const std::size_t frame = frames.add(RigidPose{});
    State state = moving_state();
    PinnedPoints saved({0, 6}, frames, 1.0, kMemory);
    saved.pin(4, frame, state);
    const auto image = [](const PinnedPoints& pins) {
        return state_test::saved_image([&](StateWriter& out) { pins.save_state(out); });
    };
    const std::vector<unsigned char> bytes = image(saved);
    PinnedPoints restored({1}, frames, 1.0, kMemory);
    StateReader in(bytes.data(), bytes.size());
    restored.restore_state(in, kPinnedBowelPoints);
    EXPECT_TRUE(restored.pinned(1)) << "the first pass only checks";
    in.start_applying();
    restored.restore_state(in, kPinnedBowelPoints);
    EXPECT_FALSE(restored.pinned(1));
    EXPECT_TRUE(restored.pinned(0) && restored.pinned(4) && restored.pinned(6));
    EXPECT_EQ(image(restored), bytes);
    // Refusals: too few control points, too few frames.
    const auto refusal = [&](std::size_t control_points, const RigidFrames& with) {
        PinnedPoints target({1}, with, 1.0, kMemory);
        StateReader reader(bytes.data(), bytes.size());
        try {
            target.restore_state(reader, control_points);
        } catch (const Error& error) {
            EXPECT_TRUE(target.pinned(1) && target.size() == 1) << "unchanged";
            return std::string(error.what());
        }
        return std::string("(no refusal)");
    };
    EXPECT_EQ(refusal(5, frames), "state: section 'pins': pinned point is 6, not below 5");
    RigidFrames none(kMemory);
    EXPECT_EQ(refusal(kPinnedBowelPoints, none), "state: section 'pins': frame of an attached point is 0, not below 0");
}

}  // namespace
}  // namespace enteron::mechanics
