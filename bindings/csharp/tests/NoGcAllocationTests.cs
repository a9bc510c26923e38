// SPDX-License-Identifier: Apache-2.0
// The calls a 1 kHz loop makes allocate nothing on the managed heap, so the garbage
// collector never pauses a physics or haptic thread that makes only them. Measured with
// GC.GetAllocatedBytesForCurrentThread (Mono 6.8 and .NET 4.8 count every allocation of
// the calling thread), after a warm-up that compiles every method once.
using System;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public class NoGcAllocationTests
    {
        private const int Steps = 10000;
        private const int Warmup = 1000;  // a grasp and a release among them

        [Test]
        public void TheCounterSeesAnAllocation()
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            var array = new byte[1000];
            long after = GC.GetAllocatedBytesForCurrentThread();
            Assert.GreaterOrEqual(after - before, 1000L, "the measure below could not fail without this");
            GC.KeepAlive(array);
        }

        [Test]
        public void TenThousandStepsOfTheHapticLoopAllocateNothing()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                Tool tool = scene.GetTool(0);
                var axis = new double[20 * 3];
                var points = new double[17 * 3];
                var contacts = new Contact[scene.GetContactSummary().capacity + 1];
                var feedback = new ToolFeedback();
                Loop(scene, tool, axis, points, contacts, ref feedback, 0, Warmup);  // JIT compilation of every call, first-step work

                int collections = GC.CollectionCount(0);
                long before = GC.GetAllocatedBytesForCurrentThread();
                Loop(scene, tool, axis, points, contacts, ref feedback, Warmup, Steps);
                long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                Console.WriteLine("GC allocations per {0} steps of the haptic loop: {1} bytes ({2} gen-0 collections meanwhile)",
                                  Steps, allocated, GC.CollectionCount(0) - collections);
                Assert.AreEqual(0L, allocated, "bytes allocated on the managed heap by " + Steps + " steps");
                Assert.AreEqual((ulong)(Warmup + Steps), scene.GetStats().steps);
                Assert.Greater(tool.ReadStats().energy_in_J, 0.0, "the loop did push the bowel");
            }
        }

        /// <summary>What a physics + haptic loop calls every tick: pose, step, feedback, stiffness, wrench, grasp state, queries.</summary>
        private static void Loop(Scene scene, Tool tool, double[] axis, double[] points, Contact[] contacts,
                                 ref ToolFeedback feedback, int from, int count)
        {
            for (int i = from; i < from + count; ++i)
            {
                double y = 0.05 - 0.04 * Math.Sin(i * 1e-3);  // back and forth across the bowel
                tool.SetPose(new Vec3(0, y, TestScenes.Radius), Quat.Identity);
                scene.Step(0.001);
                tool.ReadFeedback(ref feedback);
                Matrix3 stiffness = tool.Stiffness();
                Vec3 force, torque;
                tool.GetWrench(out force, out torque);
                if (tool.IsGrasping != feedback.IsGrasping || stiffness.M00 > 1e9) throw new InvalidOperationException();
                if (i % 1000 == 500) tool.Grasp();
                if (i % 1000 == 900) tool.Release();
                if (i % 10 == 0)
                {
                    scene.Axis(axis);
                    scene.ControlPoints(points);
                    scene.GetStats();
                    scene.GetContactSummary();
                    scene.ReadContacts(contacts);
                    tool.ReadStats();
                    tool.ReadContacts();
                }
            }
        }

        [Test]
        public void SkinUpdatesAndCopiesAllocateNothing()
        {
            using (Scene scene = Scene.FromJson(TestScenes.Minimal))
            using (var skin = new Skin(scene, SkinDesc.Default()))
            {
                skin.Update();
                MeshInfo mesh = skin.Mesh;
                var positions = new float[3 * mesh.VertexCount];
                var normals = new float[3 * mesh.VertexCount];
                var indices = new int[3 * mesh.TriangleCount];
                Frames(scene, skin, positions, normals, indices, 5);

                long before = GC.GetAllocatedBytesForCurrentThread();
                Frames(scene, skin, positions, normals, indices, 60);
                long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                Console.WriteLine("GC allocations per 60 frames of a skin: {0} bytes", allocated);
                Assert.AreEqual(0L, allocated);
            }
        }

        [Test]
        public void ExposureQueriesIntoCallerArraysAllocateNothing()
        {
            // The bowel on the floor, a disk patch beside it, an eye above: the bowel moves
            // under the tool between queries.
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                double[] points;
                uint[] triangles;
                Occlusion.Disk(0.0, 0.02, 0.03, out points, out triangles);
                using (var exposure = new Exposure(scene, ExposureDesc.Default(), points, triangles))
                {
                    Tool tool = scene.GetTool(0);
                    var spans = new double[2 * 8];
                    var hidden = new double[8];
                    var tubes = new int[8];
                    var seen = new double[exposure.ElementCount];
                    double smallest = Queries(scene, tool, exposure, spans, hidden, tubes, seen, 0, 20);  // JIT compilation

                    long before = GC.GetAllocatedBytesForCurrentThread();
                    smallest = Math.Min(smallest, Queries(scene, tool, exposure, spans, hidden, tubes, seen, 20, 200));
                    long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                    Console.WriteLine("GC allocations per 200 exposure queries ({0} samples each) with a step between: {1} bytes",
                                      exposure.Measure(Occlusion.Eye).samples, allocated);
                    Assert.AreEqual(0L, allocated);
                    Assert.Less(smallest, 1.0, "the bowel hid part of the disk: the queries did the work");
                }
            }
        }

        /// <summary>A step (the tool pushing the bowel) and a query with every array; returns the smallest fraction seen.</summary>
        private static double Queries(Scene scene, Tool tool, Exposure exposure, double[] spans, double[] hidden, int[] tubes,
                                      double[] seen, int from, int count)
        {
            double smallest = 1.0;
            for (int i = from; i < from + count; ++i)
            {
                tool.SetPose(new Vec3(0, 0.05 - 1e-4 * i, TestScenes.Radius), Quat.Identity);
                scene.Step(0.001);
                ExposureResult result = exposure.Measure(Occlusion.Eye, spans, hidden, tubes, seen);
                smallest = Math.Min(smallest, result.visible_fraction);
            }
            return smallest;
        }

        private static void Frames(Scene scene, Skin skin, float[] positions, float[] normals, int[] indices, int count)
        {
            for (int frame = 0; frame < count; ++frame)
            {
                for (int i = 0; i < 16; ++i) scene.Step(0.001);
                skin.Update();
                MeshInfo mesh = skin.CopyPositions(positions);
                skin.CopyNormals(normals);
                if (mesh.TopologyChanged) skin.CopyIndices(indices);
            }
        }
    }
}
