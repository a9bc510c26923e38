// SPDX-License-Identifier: Apache-2.0
// The Unity components, run on the UnityEngine stand-in (UnityEngineStandIn.cs): what the
// components themselves do (frames, threads, the mesh they fill, the poses they post) is
// tested here; Unity's side of it (rendering, the editor, IL2CPP) is not, and cannot be
// without Unity (bindings/unity/Documentation~/enteron.md, "What was verified").
using System;
using System.Diagnostics;
using System.Threading;
using Enteron.Tests;
using NUnit.Framework;
using UnityEngine;
using UnityEngineStandIn;

namespace Enteron.Unity.Tests
{
    [TestFixture]
    public class UnityComponentTests
    {
        private const string Minimal =
            "{\"intestine\": {\"length\": 1.0, \"control_points\": 40}, \"gravity\": [0, 0, -9.81], \"damping\": {}}";

        private const string OnTheFloor =
            "{\"intestine\": {\"length\": 0.4, \"control_points\": 17, \"shape\": {\"kind\": \"line\", \"center\": [-0.2, 0, 0.0125]}}," +
            " \"gravity\": [0, 0, -9.81], \"damping\": {}, \"environment\": [{\"type\": \"plane\"}]}";

        [TearDown]
        public void LeavePlayMode()
        {
            Player.DestroyAll();
            Player.Logged.Clear();
        }

        private static EnteronScene NewScene(string json, EnteronScene.Stepping stepping)
        {
            var root = new GameObject("scene");
            root.SetActive(false);  // as Unity loads a scene: the fields first, then Awake
            EnteronScene scene = root.AddComponent<EnteronScene>();
            scene.sceneJson = new TextAsset(json);
            scene.stepping = stepping;
            root.SetActive(true);
            Assert.IsNotNull(scene.Scene, string.Join("\n", Player.Logged.ToArray()));
            return scene;
        }

        [Test]
        public void EnteronSpaceMapsPointsRotationsAndStiffnessConsistently()
        {
            var p = new Vector3(0.1f, 0.2f, 0.3f);
            Vec3 e = EnteronSpace.ToEnteron(p);
            Assert.AreEqual(new Vec3(0.1f, 0.3f, 0.2f), e, "Unity's up (y) is Enteron's z");
            Assert.AreEqual(0f, (EnteronSpace.ToUnity(e) - p).magnitude);

            // A Unity rotation applied in Unity equals the converted rotation applied in Enteron.
            Quaternion q = Quaternion.AngleAxis(50f, new Vector3(0.3f, -1f, 0.4f)) * Quaternion.AngleAxis(-20f, new Vector3(1, 0, 0));
            Vec3 rotatedInEnteron = Rotate(EnteronSpace.ToEnteron(q), e);
            Vector3 rotatedInUnity = q * p;
            Assert.AreEqual(0.0, (EnteronSpace.ToEnteron(rotatedInUnity) - rotatedInEnteron).Length, 1e-6);
            Quaternion back = EnteronSpace.ToUnity(EnteronSpace.ToEnteron(q));
            Assert.AreEqual(0f, (back * p - q * p).magnitude, 1e-6f);

            // A tool with the identity rotation in Unity stands up (+y): its shaft, Enteron's local +z.
            Assert.AreEqual(new Vec3(0, 0, 1), Rotate(EnteronSpace.ToEnteron(Quaternion.identity), new Vec3(0, 0, 1)));

            var k = new Matrix3 { M00 = 1, M01 = 2, M02 = 3, M10 = 4, M11 = 5, M12 = 6, M20 = 7, M21 = 8, M22 = 9 };
            var dx = new Vec3(0.3, -0.2, 0.5);
            Vector3 expected = EnteronSpace.ToUnity(k * dx);
            Vector3 actual = EnteronSpace.ToUnity(k).MultiplyVector(EnteronSpace.ToUnity(dx));
            Assert.AreEqual(0f, (expected - actual).magnitude, 1e-5f, "the stiffness in Unity's frame: M K M");
        }

        /// <summary>q v q*, Hamilton's product, in Enteron's right-handed frame.</summary>
        private static Vec3 Rotate(Quat q, Vec3 v)
        {
            var u = new Vec3(q.X, q.Y, q.Z);
            Vec3 t = 2.0 * Cross(u, v);
            return v + q.W * t + Cross(u, t);
        }

        private static Vec3 Cross(Vec3 a, Vec3 b)
        {
            return new Vec3(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
        }

        [Test]
        public void ThePhysicsThreadStepsAtAboutOneKilohertzUntilDestroyed()
        {
            EnteronScene scene = NewScene(Minimal, EnteronScene.Stepping.PhysicsThread);
            Assert.AreEqual(0, scene.Steps, "the thread starts in Start, after every Awake");
            Player.Frame(0f);
            var clock = Stopwatch.StartNew();
            Thread.Sleep(500);
            long steps = scene.Steps;
            double seconds = clock.Elapsed.TotalSeconds;
            Console.WriteLine("physics thread: {0} steps in {1:F3} s of wall time, {2} late restarts", steps, seconds, scene.LateRestarts);
            Assert.LessOrEqual(steps, (long)(1000 * seconds) + 20, "paced: never faster than 1 kHz");
            Assert.Greater(steps, 50, "it steps (the machine may be loaded: only a bound from below)");
            Scene handle = scene.Scene;
            UnityEngine.Object.Destroy(scene.gameObject);
            Assert.IsNull(scene.Scene);
            Assert.IsTrue(handle.IsDisposed, "destroyed with its component");
            long after = scene.Steps;
            Thread.Sleep(50);
            Assert.AreEqual(after, scene.Steps, "the thread has stopped");
            Assert.AreEqual(0, scene.FailedSteps);
        }

        [Test]
        public void EveryFrameAndManualSteppingTakeTheirTime()
        {
            EnteronScene everyFrame = NewScene(Minimal, EnteronScene.Stepping.EveryFrame);
            for (int i = 0; i < 10; ++i) Player.Frame(1f / 60f);
            Assert.AreEqual(166, everyFrame.Steps, "10 frames of 1/60 s in 1 ms steps");
            Assert.AreEqual(0.166, everyFrame.Scene.GetStats().time_s, 1e-9);

            EnteronScene manual = NewScene(Minimal, EnteronScene.Stepping.Manual);
            Player.Frame(1f / 60f);
            Assert.AreEqual(0, manual.Steps, "a manual scene steps only when told");
            for (int i = 0; i < 5; ++i) manual.StepOnce();
            manual.Advance(0.0105);
            Assert.AreEqual(15, manual.Steps);
            Assert.Throws<InvalidOperationException>(() => NewScene(Minimal, EnteronScene.Stepping.PhysicsThread).StepOnce());
        }

        [Test]
        public void TheSkinRendererFillsTheMeshAndUploadsTheIndicesOnce()
        {
            EnteronScene scene = NewScene(Minimal, EnteronScene.Stepping.EveryFrame);
            var bowel = new GameObject("bowel");
            bowel.transform.SetParent(scene.transform, false);
            bowel.AddComponent<MeshFilter>();
            EnteronSkinRenderer renderer = bowel.AddComponent<EnteronSkinRenderer>();
            for (int i = 0; i < 6; ++i) Player.Frame(1f / 60f);

            Mesh mesh = bowel.GetComponent<MeshFilter>().sharedMesh;
            Assert.AreSame(renderer.Mesh, mesh);
            MeshInfo info = renderer.LastMesh;
            Assert.Greater(info.VertexCount, 100);
            Assert.AreEqual(6UL, info.Updates, "one update a frame");
            Assert.AreEqual(1, renderer.IndexUploads, "a stable topology: the indices once, then only vertex buffers");
            Assert.AreEqual(info.VertexCount, mesh.vertexCount);
            Assert.AreEqual(0.1, info.TimeSeconds, 1e-9, "the skin shows the last step: 6 frames of 16 or 17 steps");

            var raw = new float[3 * info.VertexCount];
            var indices = new int[3 * info.TriangleCount];
            renderer.Skin.CopyPositions(raw);
            renderer.Skin.CopyIndices(indices);
            Vector3[] vertices = mesh.vertices;
            for (int i = 0; i < info.VertexCount; ++i)
            {
                Assert.AreEqual(raw[3 * i], vertices[i].x);
                Assert.AreEqual(raw[3 * i + 1], vertices[i].z, "Enteron's y is Unity's z");
                Assert.AreEqual(raw[3 * i + 2], vertices[i].y, "Enteron's z is Unity's up");
                Vector3 offset = vertices[i] - mesh.bounds.center;
                Assert.LessOrEqual(Math.Abs(offset.y), mesh.bounds.size.y / 2 + 1e-6f, "inside the bounds");
            }
            CollectionAssert.AreEqual(indices, mesh.triangles, "the indices unchanged: a mirror turns Enteron's front faces into Unity's");
            Assert.AreEqual(info.VertexCount, mesh.uv.Length);
            Assert.AreEqual(info.VertexCount, mesh.tangents.Length);
            UnityEngine.Object.Destroy(bowel);
            Assert.IsTrue(renderer.Skin == null, "the skin is disposed with its component");
        }

        [Test]
        public void ATransformDrivesAToolAndTheToolFeelsTheBowel()
        {
            EnteronScene scene = NewScene(OnTheFloor, EnteronScene.Stepping.Manual);
            var grasper = new GameObject("grasper");
            grasper.transform.SetParent(scene.transform, false);
            grasper.transform.localPosition = new Vector3(0f, 0.0125f, 0.05f);  // beside the bowel, Unity's axes
            EnteronTool tool = grasper.AddComponent<EnteronTool>();
            tool.interpolationDelay = 0f;  // the newest frame at once: the test steps right after each frame
            Player.Frame(1f / 60f);
            scene.StepOnce();  // the first tick adds the tool (a driving call, queued by Start)
            Assert.IsNotNull(tool.Tool);
            Assert.AreEqual(1, scene.Scene.ToolCount);
            double largest = 0;
            for (int i = 1; i <= 600; ++i)  // 6 cm across the bowel, along Unity's -z (Enteron's -y)
            {
                grasper.transform.localPosition = new Vector3(0f, 0.0125f, 0.05f - 1e-4f * i);
                Player.Frame(0.001f);
                scene.StepOnce();
                largest = Math.Max(largest, tool.Force.magnitude);
            }
            Player.Frame(0.001f);
            ToolFeedback feedback = tool.Feedback;
            Assert.AreEqual(EnteronSpace.ToEnteron(grasper.transform.localPosition), feedback.commanded_position_m);
            Assert.Greater(largest, 0.0, "the tool pushed the bowel");
            Assert.LessOrEqual(largest, 5.0 * (1 + 1e-6), "within max_force");
            Assert.Greater(tool.Force.z, 0f, "pushed along -z, the bowel pushes back along +z");
            Assert.Less(tool.Stiffness.m22, 0f, "and harder the further the tip goes");

            grasper.transform.localRotation = Quaternion.AngleAxis(30f, new Vector3(1, 0, 0));
            Player.Frame(0.001f);
            scene.StepOnce();
            Quat expected = EnteronSpace.ToEnteron(grasper.transform.localRotation);
            Quat actual = tool.ReadFeedback().orientation_wxyz;
            Assert.AreEqual(expected.W, actual.W, 1e-6);
            Assert.AreEqual(expected.X, actual.X, 1e-6);

            UnityEngine.Object.Destroy(grasper);
            scene.StepOnce();
            Assert.AreEqual(0, scene.Scene.ToolCount, "a tool the component added goes with it");
        }

        [Test]
        public void AHapticDeviceThreadDrivesAToolWithoutTheMainThread()
        {
            EnteronScene scene = NewScene(OnTheFloor, EnteronScene.Stepping.PhysicsThread);
            var grasper = new GameObject("device tool");
            grasper.transform.SetParent(scene.transform, false);
            EnteronTool tool = grasper.AddComponent<EnteronTool>();
            tool.poseSource = EnteronTool.PoseSource.Device;
            Player.Frame(1f / 60f);
            var clock = Stopwatch.StartNew();
            while (tool.Tool == null && clock.Elapsed.TotalSeconds < 10) Thread.Sleep(1);
            Assert.IsNotNull(tool.Tool, "added by the physics thread");
            var target = new Vector3(0.05f, 0.1f, 0.02f);
            Exception failed = null;
            ToolFeedback last = new ToolFeedback();
            var device = new Thread(() =>
            {
                try
                {
                    while (clock.Elapsed.TotalSeconds < 12)
                    {
                        tool.PostDevicePose(target, Quaternion.identity);  // the device's servo loop
                        last = tool.ReadFeedback();
                        if (last.commanded_position_m.Equals(EnteronSpace.ToEnteron(target))) return;
                        Thread.Sleep(1);
                    }
                }
                catch (Exception error)
                {
                    failed = error;
                }
            });
            device.Start();
            device.Join();
            Assert.IsNull(failed);
            Assert.AreEqual(EnteronSpace.ToEnteron(target), last.commanded_position_m, "a step took the device's pose");
        }

        [Test]
        public void ThePoseInterpolatorPlaysTheFramesBackSmoothly()
        {
            var poses = new PoseInterpolator();
            Vec3 position;
            Quat orientation;
            Assert.IsFalse(poses.Read(0, out position, out orientation), "nothing before the first sample");
            poses.Write(1000, new Vec3(0, 0, 0), Quat.Identity);
            poses.Write(2000, new Vec3(1, 2, 3), new Quat(0, 0, 0, 1));  // half a turn about z
            Assert.IsTrue(poses.Read(1500, out position, out orientation));
            Assert.AreEqual(new Vec3(0.5, 1, 1.5), position);
            Assert.AreEqual(Math.Sqrt(0.5), orientation.W, 1e-12, "halfway: a quarter turn");
            Assert.AreEqual(Math.Sqrt(0.5), orientation.Z, 1e-12);
            poses.Read(500, out position, out orientation);
            Assert.AreEqual(Vec3.Zero, position, "held before the older sample");
            poses.Read(5000, out position, out orientation);
            Assert.AreEqual(new Vec3(1, 2, 3), position, "held after the newer one");
        }

        [Test]
        public void TheComponentsUseNothingOfTheStandInButUnitysApi()
        {
            string runtime = TestPaths.Source("bindings/unity");
            foreach (string file in System.IO.Directory.GetFiles(runtime, "*.cs", System.IO.SearchOption.AllDirectories))
                StringAssert.DoesNotContain("UnityEngineStandIn", System.IO.File.ReadAllText(file), file);
        }
    }
}
