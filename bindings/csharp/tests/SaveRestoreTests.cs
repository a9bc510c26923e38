// SPDX-License-Identifier: Apache-2.0
// Save and restore through the binding: a restored scene continues bit for bit, in the
// same scene and in another made from the same description; a damaged or foreign state
// is refused and changes nothing.
using System;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public class SaveRestoreTests
    {
        /// <summary>Pushes for a while and returns the control points and the tool's force at the end.</summary>
        private static double[] Continue(Scene scene, int fromStep, int steps)
        {
            Tool tool = scene.GetTool(0);
            TestScenes.Push(scene, tool, fromStep, steps);
            var points = new double[17 * 3 + 3];
            scene.ControlPoints(points);
            Vec3 force = tool.ReadFeedback().force_N;
            points[17 * 3] = force.X;
            points[17 * 3 + 1] = force.Y;
            points[17 * 3 + 2] = force.Z;
            return points;
        }

        [Test]
        public void ARestoredSceneContinuesBitForBit()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            using (Scene other = Scene.FromJson(TestScenes.OnTheFloor))
            {
                Continue(scene, 0, 300);  // the tool presses into the bowel by now: contacts, self-contacts
                byte[] saved = scene.SaveState();
                Assert.Greater(saved.Length, 0);
                Assert.AreEqual(saved.Length, scene.SaveStateSize());
                double[] first = Continue(scene, 300, 300);

                scene.RestoreState(saved);
                Assert.AreEqual(300UL, scene.GetStats().steps, "back to the saved instant");
                Bits.AssertSame(first, Continue(scene, 300, 300), "the same scene after restoring");

                other.RestoreState(saved);
                Bits.AssertSame(first, Continue(other, 300, 300), "another scene from the same description");

                var buffer = new byte[saved.Length + 100];
                int length = other.SaveState(buffer);
                other.RestoreState(buffer, length);
                Assert.AreEqual(600UL, other.GetStats().steps);
            }
        }

        [Test]
        public void ADamagedOrForeignStateIsRefusedAndChangesNothing()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            using (Scene minimal = Scene.FromJson(TestScenes.Minimal))
            {
                Continue(scene, 0, 50);
                byte[] saved = scene.SaveState();
                Continue(scene, 50, 10);

                var damaged = (byte[])saved.Clone();
                damaged[damaged.Length / 2] ^= 0x40;
                var error = Assert.Throws<EnteronException>(() => scene.RestoreState(damaged));
                Assert.AreEqual(Status.InvalidArgument, error.Status);
                Assert.AreEqual(60UL, scene.GetStats().steps, "unchanged");

                error = Assert.Throws<EnteronException>(() => minimal.RestoreState(saved));
                Assert.AreEqual(Status.InvalidArgument, error.Status, "saved from another scene");
                StringAssert.Contains("scene", error.Message);

                error = Assert.Throws<EnteronException>(() => scene.RestoreState(saved, saved.Length / 2));
                Assert.AreEqual(Status.InvalidArgument, error.Status, "truncated");

                error = Assert.Throws<EnteronException>(() => scene.SaveState(new byte[8]));
                Assert.AreEqual(Status.BufferTooSmall, error.Status);
                Assert.Throws<ArgumentOutOfRangeException>(() => scene.RestoreState(saved, saved.Length + 1));
            }
        }
    }
}
