// SPDX-License-Identifier: Apache-2.0
// Contacts through the binding: the list, its summary and each tool's part, and the sum
// the header promises (the tool's contact forces are minus its wrench).
using System;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public class ContactTests
    {
        [Test]
        public void TheListTheSummaryAndTheToolsContactsAgree()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                Tool tool = scene.GetTool(0);
                TestScenes.Push(scene, tool, 0, 500);  // 5 cm: the tool presses into the bowel
                ContactSummary summary = scene.GetContactSummary();
                Assert.Greater(summary.tool_contacts, 0U, "the tool touches");
                Assert.Greater(summary.obstacle_contacts, 0U, "the bowel lies on the floor");
                Assert.AreEqual(summary.found, summary.self_contacts + summary.obstacle_contacts + summary.tool_contacts);
                Assert.AreEqual(500UL, summary.steps);

                var contacts = new Contact[summary.capacity + 1];
                int count = scene.ReadContacts(contacts);
                Assert.AreEqual((int)summary.listed, count);
                Vec3 toolForceOnBowel = Vec3.Zero;
                ContactKind previous = ContactKind.Tool;
                for (int i = 0; i < count; ++i)
                {
                    Contact contact = contacts[i];
                    Assert.LessOrEqual((int)contact.kind, (int)previous, "tools, then obstacles, then self-contacts");
                    Assert.That(contact.u, Is.InRange(0.0, 1.0));
                    Assert.Greater(contact.depth_m, 0.0);
                    Assert.AreEqual(1.0, contact.normal.Length, 1e-9, "unit normal");
                    if (contact.kind == ContactKind.Tool)
                    {
                        Assert.AreEqual(ContactKind.Tool, previous, "the tools' contacts come first");
                        Assert.AreEqual(0, contact.index);
                        toolForceOnBowel = toolForceOnBowel + contact.force_N;
                    }
                    else
                    {
                        Assert.AreEqual(-1.0, contact.other_u, "only a self-contact has another u");
                    }
                    previous = contact.kind;
                }
                // Proxy mode: the bowel's contacts push the proxy, and the wrench is the
                // coupling's; once the proxy rests (slow push), they balance within the
                // coupling's damping.
                Vec3 force, torque;
                tool.GetWrench(out force, out torque);
                Assert.AreEqual(0.0, (toolForceOnBowel + force).Length, 0.05 * Math.Max(force.Length, 1e-3),
                                "the tool's contact forces on the bowel are minus its wrench");

                ToolContacts touched = tool.ReadContacts(new double[2]);
                Assert.Greater(touched.contacts, 0U);
                Assert.Greater(touched.range_count, 0U);
                var ranges = new double[2 * touched.range_count];
                touched = tool.ReadContacts(ranges);
                for (int r = 0; r < touched.range_count; ++r)
                {
                    Assert.That(ranges[2 * r], Is.InRange(0.0, 1.0));
                    Assert.LessOrEqual(ranges[2 * r], ranges[2 * r + 1], "first u <= last u");
                }
                Assert.Greater(touched.contact_impulse_magnitude_Ns, 0.0);
                Assert.AreEqual(-1.0, touched.grasp_u);
            }
        }

        [Test]
        public void ATooSmallListIsRefusedAndNothingIsWritten()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                for (int i = 0; i < 50; ++i) scene.Step(0.001);  // it settles onto the floor
                Assert.Greater(scene.GetContactSummary().listed, 1U, "the bowel lies on the floor at many spheres");
                var one = new Contact[1];
                var error = Assert.Throws<EnteronException>(() => scene.ReadContacts(one));
                Assert.AreEqual(Status.BufferTooSmall, error.Status);
                Assert.AreEqual(0.0, one[0].depth_m, "nothing copied");
                Assert.Throws<ArgumentException>(() => scene.ReadContacts(new Contact[0]));
            }
        }
    }
}
