// SPDX-License-Identifier: Apache-2.0
// What a tool reports (lib/collision/tool_outputs.h): the sums of an attempt are the
// durations times what the bowel received, the linearised force at the substep's end in an
// implicit evaluation; the accepted wrench is minus their mean, never above max_force, with
// the passivity observer counting its work; the output copies the accepted state.
#include "collision/tool_outputs.h"

#include <gtest/gtest.h>

#include <memory_resource>
#include <vector>

#include "spline/catmull_rom.h"

namespace {

using enteron::Mat3;
using enteron::Vec3;
using enteron::mechanics::State;
using namespace enteron::collision;

constexpr std::size_t kToolOutputsPoints = 6;

enteron::spline::SegmentWeights tool_outputs_weights() {
    enteron::spline::SegmentWeights w;
    w.first = 1;
    w.w = {-0.0625, 0.5625, 0.5625, -0.0625};
    return w;
}

// One sphere contact of a tool, pushing the bowel down with 2 N, and its list.
struct ToolOutputsBench {
    ToolOutputsBench() : state(std::pmr::new_delete_resource()), force(3 * kToolOutputsPoints, 0.0) {
        state.resize(kToolOutputsPoints);
        contacts.reserve(2);
        contacts.begin(force.data(), nullptr);
        ContactForce law{};
        law.force = Vec3(0.0, 0.0, -2.0);
        law.normal_force = 2.0;
        law.stiffness = 1000.0;
        law.damping = 0.5;
        contacts.add_sphere(3, tool_outputs_weights(), 0.002, law, -Vec3::UnitZ(), 1.0, Vec3::Zero(), Vec3::Zero(),
                            Vec3(0.1, 0.0, 0.0));
        tool.evaluation.first_contact = 0;
        tool.evaluation.contact_count = 1;
        tool.evaluation.sphere_contacts = 1;
        tool.evaluation.stiffness = 7.0 * Mat3::Identity();
    }
    State state;
    std::vector<double> force;
    ToolContacts contacts{std::pmr::new_delete_resource()};
    ContactLog log{ContactKind::tool, 8, std::pmr::new_delete_resource()};
    ToolState tool;
};

TEST(ToolOutputs, AnExplicitAttemptSumsWhatTheBowelReceivedTimesItsDuration) {
    ToolOutputsBench bench;
    add_evaluation_received(bench.tool, 0, bench.contacts, 0.25e-3, nullptr, Vec3::Zero(), bench.log);
    add_evaluation_received(bench.tool, 0, bench.contacts, 0.75e-3, nullptr, Vec3::Zero(), bench.log);
    const AttemptSums& sums = bench.tool.attempt;
    EXPECT_NEAR(sums.duration, 1e-3, 1e-18);
    EXPECT_LT((sums.impulse - Vec3(0.0, 0.0, -2e-3)).norm(), 1e-15);
    // The bowel's contact pushes the tool up: the contacts' impulse on the tool.
    EXPECT_LT((sums.contact_impulse - Vec3(0.0, 0.0, 2e-3)).norm(), 1e-15);
    EXPECT_NEAR(sums.contact_impulse_magnitude, 2e-3, 1e-15);
    // The torque on the tool about its tip: arm x (-force).
    EXPECT_LT((sums.angular_impulse - 1e-3 * Vec3(0.1, 0.0, 0.0).cross(Vec3(0.0, 0.0, 2.0))).norm(), 1e-15);
    EXPECT_EQ(sums.stiffness, bench.tool.evaluation.stiffness);
    EXPECT_EQ(sums.contacts, 1u);
    ASSERT_EQ(bench.log.size(), 2u) << "each evaluation's sphere contacts, with what the bowel received";
    EXPECT_EQ(bench.log.begin()->force, Vec3(0.0, 0.0, -2.0));
}

TEST(ToolOutputs, AnImplicitEvaluationCountsTheLinearisedForceAtTheSubstepsEnd) {
    ToolOutputsBench bench;
    const double h = 1e-3;
    State after = bench.state;
    // Every control point 0.1 mm down and moving at 0.1 m/s down: the spring and the damper
    // of the contact give way by H dq + C dv.
    for (std::size_t i = 0; i < kToolOutputsPoints; ++i) {
        after.q[3 * i + 2] = -1e-4;
        after.v[3 * i + 2] = -0.1;
    }
    add_evaluation_received(bench.tool, 0, bench.contacts, h, &after, Vec3::Zero(), bench.log);
    const ToolContact& c = bench.contacts[0];
    const Vec3 expected = c.force - c.stiffness * Vec3(0.0, 0.0, -1e-4) - c.damping * Vec3(0.0, 0.0, -0.1);
    EXPECT_LT((bench.tool.attempt.impulse - h * expected).norm(), 1e-15);
    EXPECT_GT(bench.tool.attempt.impulse.z(), h * c.force.z()) << "less than the evaluation's push";
}

TEST(ToolOutputs, TheAcceptedWrenchIsMinusTheMeanForceWithinMaxForce) {
    for (const double max_force : {5.0, 1.5}) {
        ToolOutputsBench bench;
        bench.tool.settings.max_force = max_force;
        bench.tool.target.position = Vec3(0.0, 0.0, -0.001);  // the tool pressed down 1 mm
        add_evaluation_received(bench.tool, 0, bench.contacts, 1e-3, nullptr, Vec3::Zero(), bench.log);
        accept_outputs(bench.tool);
        const ToolWrench& wrench = bench.tool.accepted.wrench;
        EXPECT_NEAR(wrench.force.z(), std::min(2.0, max_force), 1e-12) << "up on the tool";
        EXPECT_NEAR(wrench.force.norm(), std::min(2.0, max_force), 1e-12);
        EXPECT_EQ(bench.tool.accepted.stiffness, bench.tool.evaluation.stiffness);
        EXPECT_EQ(bench.tool.accepted.contacts, 1u);
        // The tool went down against the force up on it: it did work on the scene.
        EXPECT_NEAR(bench.tool.accepted.observer.stats().energy_in, std::min(2.0, max_force) * 0.001, 1e-15);
        ToolOutput output;
        write_output(bench.tool, output);
        EXPECT_EQ(output.wrench.force, wrench.force);
        EXPECT_EQ(output.contacts, 1u);
        EXPECT_EQ(output.contact_impulse, bench.tool.accepted.contact_impulse);
    }
}

}  // namespace
