// SPDX-License-Identifier: Apache-2.0
// The proxy tool's contacts (lib/collision/tool_proxy_contacts.h) on a straight bowel: with
// the device pushed deep into it, the proxy rests on its surface and what it gives the bowel
// balances the coupling force, within max_force; in an implicit evaluation its body joins
// the border; a grasp that would need the coupling past max_force slips.
#include "collision/tool_proxy_contacts.h"

#include <gtest/gtest.h>

#include <memory_resource>
#include <vector>

#include "collision/collision_fixtures.h"
#include "mechanics/bordered_system.h"
#include "mechanics/system_matrix.h"

namespace {

using namespace collision_test;
using enteron::Vec3;
using namespace enteron::collision;

// A vertical proxy tool above the bowel's middle, the device commanded to `device`.
ToolState vertical_tool(const Vec3& device, double max_force) {
    ToolState tool;
    tool.settings.max_force = max_force;
    tool.contact.stiffness = proxy_contact_stiffness(tool.contact.stiffness, max_force, kRadius);
    tool.current.position = tool.target.position = device;
    tool.proxy.position = {0.2, 0.0, kRadius + tool.settings.radius + 0.002};
    return tool;
}

using ToolProxyContactsBench = ToolLawBench<ProxyContacts>;

TEST(ProxyContacts, PushedDeepTheProxyRestsOnTheSurfaceAndTheBowelGetsTheCouplingForce) {
    ToolProxyContactsBench bench;
    const double max_force = 3.0;
    ToolState tool = vertical_tool(Vec3(0.2, 0.0, -0.05), max_force);  // the device 5 cm into the bowel
    bench.evaluate(tool, nullptr);
    ASSERT_GT(bench.contacts.size(), 0u);
    const double reach = kRadius + tool.settings.radius;
    EXPECT_GT(tool.evaluation.rested.position.z(), 0.8 * reach) << "on the surface, not through the bowel";
    Vec3 given = Vec3::Zero();
    for (std::size_t k = 0; k < bench.contacts.size(); ++k) given += bench.contacts[k].force;
    // The coupling pulls the proxy down with max_force (saturated); the bowel gets it all.
    EXPECT_NEAR(given.norm(), max_force, 1e-6 * max_force);
    EXPECT_LT(given.z(), 0.0);
    EXPECT_EQ(tool.evaluation.sphere_contacts, bench.contacts.size());
    EXPECT_FALSE(tool.evaluation.has_body) << "explicit: no border";
}

TEST(ProxyContacts, InAnImplicitEvaluationTheProxyJoinsTheBorder) {
    ToolProxyContactsBench bench;
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    enteron::mechanics::SystemMatrix system(memory);
    system.resize(bench.axis.state.q.size());
    system.set_zero();
    enteron::mechanics::BorderedSystem border(memory);
    border.reserve(1, bench.axis.state.q.size());
    border.clear();
    std::vector<double> hv(bench.axis.state.q.size(), 0.0);
    const enteron::mechanics::Linearization lin{&system, 1e-3, hv.data(), nullptr, &border};
    ToolState tool = vertical_tool(Vec3(0.2, 0.0, 0.0), 3.0);
    bench.evaluate(tool, &lin);
    EXPECT_TRUE(tool.evaluation.has_body);
    EXPECT_EQ(border.size(), 1u);
    EXPECT_EQ(tool.evaluation.body, 0u);
}

TEST(ProxyContacts, AGraspThatWouldNeedMoreThanMaxForceSlips) {
    ToolProxyContactsBench bench;
    ToolState tool = vertical_tool(Vec3(0.2, 0.0, 0.5), 1.0);  // the device half a metre up
    tool.proxy.position = {0.2, 0.0, 0.3};
    tool.grasp.holding = true;
    tool.grasp.point = bench.spheres[bench.spheres.size() / 2].weights;
    bench.evaluate(tool, nullptr, kRadius + tool.settings.radius);
    EXPECT_TRUE(tool.grasp.slipped);
    for (std::size_t k = 0; k < bench.contacts.size(); ++k) EXPECT_NE(bench.contacts[k].sphere, ToolContact::kGrasp);
    // Close to the bowel the coupling holds it.
    ToolState near = vertical_tool(Vec3(0.2, 0.0, 0.022), 5.0);
    near.grasp.holding = true;
    near.grasp.point = tool.grasp.point;
    bench.evaluate(near, nullptr, kRadius + near.settings.radius);
    EXPECT_FALSE(near.grasp.slipped);
}

}  // namespace
