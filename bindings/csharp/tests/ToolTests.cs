// SPDX-License-Identifier: Apache-2.0
// Tools through the binding: a push that moves the bowel with a bounded force read back in
// every form the C API gives it, a grasp that lifts, a removal.
using System;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public class ToolTests
    {
        [Test]
        public void APushMovesTheBowelWithABoundedForceReadBackEveryWay()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                Assert.AreEqual(1, scene.ToolCount);
                Tool tool = scene.GetTool(0);
                var axis = new double[101 * 3];
                scene.Axis(axis);
                double startY = axis[50 * 3 + 1];
                double largest = 0;
                bool touched = false;
                for (int i = 1; i <= 800; ++i)  // 8 cm along -y at 0.1 m/s
                {
                    TestScenes.Push(scene, tool, i - 1, 1);
                    ToolFeedback feedback = tool.ReadFeedback();
                    Vec3 force, torque;
                    tool.GetWrench(out force, out torque);
                    Assert.AreEqual(feedback.force_N, force, "feedback and wrench: one snapshot, the same force");
                    Assert.AreEqual(feedback.torque_Nm, torque);
                    Assert.AreEqual((ulong)i, feedback.steps);
                    Assert.LessOrEqual(force.Length, TestScenes.MaxForce * (1 + 1e-12), "bounded by max_force");
                    largest = Math.Max(largest, force.Length);
                    if (feedback.contacts > 0)
                    {
                        touched = true;
                        Matrix3 stiffness = tool.Stiffness();
                        Assert.AreEqual(feedback.stiffness_N_per_m, stiffness, "feedback and stiffness agree");
                        Assert.Less(stiffness.M11, 0.0, "the bowel pushes back harder as the tip goes further along -y");
                    }
                }
                Assert.IsTrue(touched, "the tool reached the bowel");
                scene.Axis(axis);
                Assert.Greater(startY - axis[50 * 3 + 1], 0.01, "the bowel was pushed more than 1 cm along -y");
                Assert.Greater(largest, 0.0);
                ToolStats stats = tool.ReadStats();
                Assert.AreEqual(800UL, stats.steps);
                Assert.GreaterOrEqual(stats.energy_in_J, 0.0);
                Assert.Greater(stats.energy_in_J, 0.0, "the tool did work on the bowel");
            }
        }

        [Test]
        public void AGraspLiftsTheBowelAndAReleaseLetsGo()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                Tool tool = scene.GetTool(0);
                // Down onto the middle of the bowel from above, then grasp.
                var above = new Vec3(0, 0, 0.05);
                tool.SetPose(above, Quat.Identity);
                scene.Step(0.001);
                for (int i = 1; i <= 100; ++i)
                {
                    tool.SetPose(new Vec3(0, 0, 0.05 - 0.0003 * i), Quat.Identity);  // to z = 0.02
                    scene.Step(0.001);
                }
                Assert.IsFalse(tool.IsGrasping);
                tool.Grasp();
                scene.Step(0.001);
                Assert.IsTrue(tool.IsGrasping, "the bowel was within reach");
                Assert.IsTrue(tool.ReadFeedback().IsGrasping);
                for (int i = 1; i <= 300; ++i)
                {
                    tool.SetPose(new Vec3(0, 0, 0.02 + 0.0002 * i), Quat.Identity);  // up to z = 0.08
                    scene.Step(0.001);
                }
                var axis = new double[101 * 3];
                scene.Axis(axis);
                double highest = double.MinValue;
                for (int i = 0; i < 101; ++i) highest = Math.Max(highest, axis[3 * i + 2]);
                Assert.IsTrue(tool.IsGrasping, "the grasp held through the lift");
                Assert.Greater(highest, 0.04, "the grasped bowel was lifted");
                ToolContacts held = tool.ReadContacts();
                Assert.AreEqual(1, held.grasping);
                Assert.That(held.grasp_u, Is.InRange(0.3, 0.7), "held near the middle");
                tool.Release();
                scene.Step(0.001);
                Assert.IsFalse(tool.IsGrasping);
                Assert.AreEqual(-1.0, tool.ReadContacts().grasp_u);
            }
        }

        [Test]
        public void AnAddedToolIsRemovedAndThenNotFound()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                ToolDesc desc = ToolDesc.Default();
                desc.position_m = new Vec3(0.1, 0.2, 0.1);
                desc.mode = ToolMode.Direct;
                Tool second = scene.AddTool(desc);
                Assert.AreEqual(1, second.Id);
                Assert.AreSame(scene, second.Scene);
                Assert.AreEqual(2, scene.ToolCount);
                scene.Step(0.001);
                Assert.AreEqual(new Vec3(0.1, 0.2, 0.1), second.ReadFeedback().proxy_position_m, "direct mode: where it was put");
                ToolDesc read = second.ReadDescription();
                Assert.AreEqual(ToolMode.Direct, read.mode, "ent_tool_read_desc: what it was added with");
                Assert.AreEqual(desc.position_m, read.position_m);
                second.Remove();
                scene.Step(0.001);
                Assert.AreEqual(1, scene.ToolCount);
                var error = Assert.Throws<EnteronException>(() => second.SetPose(Vec3.Zero, Quat.Identity));
                Assert.AreEqual(Status.NotFound, error.Status);
                Assert.AreEqual("ent_tool_set_pose", error.Function);
                Assert.AreEqual(Status.NotFound, Assert.Throws<EnteronException>(() => scene.GetTool(1)).Status);
                Assert.AreEqual(Status.NotFound, Assert.Throws<EnteronException>(() => second.Remove()).Status);
            }
        }
    }
}
