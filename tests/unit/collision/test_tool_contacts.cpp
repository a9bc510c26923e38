// SPDX-License-Identifier: Apache-2.0
// The list of a tools' evaluation's contacts (lib/collision/tool_contacts.h): a contact's force
// reaches the control points through its weights; in an implicit evaluation its block
// scale (h^2 H + h C) and its H v reach the system; a grasp's blocks are the grasp law's;
// the summary counts the sphere contacts (not the grasp) and keeps the deepest.
#include "collision/tool_contacts.h"

#include <gtest/gtest.h>

#include <memory_resource>
#include <vector>

#include "mechanics/system_matrix.h"

namespace {

using enteron::Mat3;
using enteron::Vec3;
using enteron::mechanics::Linearization;
using enteron::mechanics::SystemMatrix;
using namespace enteron::collision;

constexpr std::size_t kPoints = 8;
constexpr double kH = 1e-3;  // s

// Weights on control points 2..5 that sum to one.
enteron::spline::SegmentWeights weights() {
    enteron::spline::SegmentWeights w;
    w.first = 2;
    w.w = {-0.0625, 0.5625, 0.5625, -0.0625};
    return w;
}

// The 3 x 3 block of the system between control points i and j.
Mat3 block(const SystemMatrix& system, std::size_t i, std::size_t j) {
    Mat3 b;
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) b(r, c) = system.at(3 * i + r, 3 * j + c);
    return b;
}

struct Evaluation {
    Evaluation() : system(std::pmr::new_delete_resource()), force(3 * kPoints, 0.0), hv(3 * kPoints, 0.0) {
        system.resize(3 * kPoints);
        system.set_zero();
        lin = Linearization{&system, kH, hv.data()};
        contacts.reserve(4);
    }
    SystemMatrix system;
    std::vector<double> force, hv;
    Linearization lin{};
    ToolContacts contacts{std::pmr::new_delete_resource()};
};

TEST(ToolContacts, ASpheresContactReachesTheControlPointsAndTheImplicitSystem) {
    Evaluation e;
    e.contacts.begin(e.force.data(), &e.lin);
    const ContactParameters law;
    const Vec3 normal(0.0, 0.6, 0.8), velocity(0.01, -0.02, 0.03);
    const ContactForce cf = contact_force(law, 0.002, normal, velocity);
    const double scale = 0.5;
    const ToolContact& contact =
        e.contacts.add_sphere(7, weights(), 0.002, cf, normal, scale, Vec3(0.1, 0.0, 0.0), velocity, Vec3::Zero());
    EXPECT_EQ(contact.sphere, 7u);
    EXPECT_LT((contact.force - scale * cf.force).norm(), 1e-15);
    // The force, spread by the weights.
    for (std::size_t k = 0; k < 4; ++k) {
        const Vec3 expected = weights().w[k] * contact.force;
        EXPECT_LT((enteron::point_at(e.force.data(), 2 + k) - expected).norm(), 1e-15) << k;
    }
    // The block w_j w_k (h^2 H + h C), and H v.
    const Mat3 system_block = kH * kH * contact.stiffness + kH * contact.damping;
    const enteron::spline::SegmentWeights w = weights();
    for (std::size_t j = 0; j < 4; ++j)
        for (std::size_t k = 0; k <= j; ++k)
            EXPECT_LT((block(e.system, 2 + j, 2 + k) - w.w[j] * w.w[k] * system_block).norm(), 1e-15) << j << k;
    for (std::size_t k = 0; k < 4; ++k)
        EXPECT_LT((enteron::point_at(e.hv.data(), 2 + k) - w.w[k] * (contact.stiffness * velocity)).norm(), 1e-12);
    EXPECT_EQ(e.contacts.summary().count, 1u);
    EXPECT_EQ(e.contacts.summary().max_penetration, 0.002);
}

TEST(ToolContacts, AGraspsBlocksAreTheGraspLaws) {
    Evaluation e;
    e.contacts.begin(e.force.data(), &e.lin);
    const GraspLaw law{200.0, 2.0};
    const Vec3 point(0.1, 0.0, 0.0), velocity(0.0, 0.01, 0.0);
    const GraspSpring spring = grasp_spring(law, 0.01, point + Vec3(0.0, 0.0, 0.03), Vec3::Zero(), point, velocity);
    ASSERT_TRUE(spring.taut);
    const ToolContact& contact = e.contacts.add_grasp(spring, law, weights(), 1.0, point, velocity);
    EXPECT_EQ(contact.sphere, ToolContact::kGrasp);
    EXPECT_EQ(contact.stiffness, grasp_stiffness(spring));
    EXPECT_EQ(contact.damping, law.damping * Mat3::Identity());
    const Mat3 system_block = kH * kH * grasp_stiffness(spring) + kH * law.damping * Mat3::Identity();
    const enteron::spline::SegmentWeights w = weights();
    EXPECT_LT((block(e.system, 3, 3) - w.w[1] * w.w[1] * system_block).norm(), 1e-15);
    EXPECT_EQ(e.contacts.summary().count, 0u) << "the grasp is no sphere contact";
}

TEST(ToolContacts, AnExplicitEvaluationLeavesTheSystemAloneAndANewOneForgetsTheLast) {
    Evaluation e;
    e.contacts.begin(e.force.data(), nullptr);
    EXPECT_EQ(e.contacts.h(), 0.0);
    const ContactForce cf = contact_force(ContactParameters{}, 0.001, Vec3::UnitZ(), Vec3::Zero());
    e.contacts.add_sphere(0, weights(), 0.001, cf, Vec3::UnitZ(), 1.0, Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
    e.contacts.add_sphere(1, weights(), 0.003, cf, Vec3::UnitZ(), 1.0, Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
    EXPECT_EQ(block(e.system, 3, 3), Mat3::Zero());
    EXPECT_EQ(e.contacts.size(), 2u);
    EXPECT_EQ(e.contacts.summary().count, 2u);
    EXPECT_EQ(e.contacts.summary().max_penetration, 0.003);
    e.contacts.begin(e.force.data(), nullptr);
    EXPECT_EQ(e.contacts.size(), 0u);
    EXPECT_EQ(e.contacts.summary().count, 0u);
}

}  // namespace
