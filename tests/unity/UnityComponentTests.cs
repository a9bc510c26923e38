// SPDX-License-Identifier: Apache-2.0
// The Unity components, run on the UnityEngine stand-in (UnityEngineStandIn.cs): what the
// components themselves do (frames, threads, the mesh they fill, the poses they post) is
// tested here; Unity's side of it (rendering, the editor, IL2CPP) is not, and cannot be
// without Unity (bindings/unity/Documentation~/enteron.md, "What was verified").
using System;
using System.Diagnostics;
using System.Linq;
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

        // tests/capi/test_exposure.cpp's tube (TestSupport.cs, Occlusion): 2 m along x with its
        // axis 5 cm above the floor's plane, at rest; a plane obstacle (an organ) 10 cm below.
        private const string StraightTube =
            "{\"intestine\": {\"length\": 2.0, \"control_points\": 81, \"radius\": 0.0125," +
            " \"shape\": {\"kind\": \"line\", \"center\": [-1.0, 0, 0.05]}}," +
            " \"environment\": [{\"type\": \"plane\", \"point\": [0, 0, -0.1]}]}";

        /// <summary>A child of the scene's object with a MeshFilter holding these triangles (x y z in Enteron's frame, converted).</summary>
        private static GameObject Target(EnteronScene scene, string name, double[] xyz, uint[] triangles)
        {
            var vertices = new Vector3[xyz.Length / 3];
            for (int v = 0; v < vertices.Length; ++v)
                vertices[v] = EnteronSpace.ToUnity(new Vec3(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
            var indices = new int[triangles.Length];
            for (int i = 0; i < indices.Length; ++i) indices[i] = (int)triangles[i];
            var mesh = new Mesh();
            mesh.SetVertices(vertices, 0, vertices.Length);
            mesh.SetIndices(indices, 0, indices.Length, MeshTopology.Triangles, 0, true, 0);
            var target = new GameObject(name);
            target.transform.SetParent(scene.transform, false);
            target.AddComponent<MeshFilter>().sharedMesh = mesh;
            return target;
        }

        private static Transform Camera(EnteronScene scene, Vector3 position)
        {
            var camera = new GameObject("laparoscope");
            camera.transform.SetParent(scene.transform, false);
            camera.transform.localPosition = position;
            return camera.transform;
        }

        [Test]
        public void AnExposureMeasuresATargetFromTheCameraEveryFrame()
        {
            // A disk on the edge of the band the tube hides from 30 cm above: half of it seen.
            // Its mesh is centred on its object, which stands on the band's edge (Unity's z is
            // Enteron's y): the target is placed where its object is.
            EnteronScene scene = NewScene(StraightTube, EnteronScene.Stepping.Manual);
            double[] xyz;
            uint[] fan;
            Occlusion.Disk(0.0, 0.0, 0.01, out xyz, out fan);
            GameObject disk = Target(scene, "disk", xyz, fan);
            disk.transform.localPosition = new Vector3(0f, 0f, (float)Occlusion.BandHalfWidth());
            Transform camera = Camera(scene, new Vector3(0f, (float)Occlusion.EyeHeight, 0f));
            EnteronExposure exposure = disk.AddComponent<EnteronExposure>();
            exposure.viewpoint = camera;
            exposure.samplesPerEdge = 8;
            Player.Frame(1f / 60f);
            Assert.IsNotNull(exposure.Exposure, string.Join("\n", Player.Logged.ToArray()));
            Assert.AreEqual(0.5, exposure.VisibleFraction, 0.01, "tests/capi/test_exposure.cpp's half-covered disk");
            Assert.AreEqual(64u * 64u, exposure.Result.samples);
            Assert.AreEqual(1u, exposure.Result.span_count, "the tube above the disk");
            Assert.Less(exposure.SpansU[0], 0.5);
            Assert.Greater(exposure.SpansU[1], 0.5);
            Assert.AreEqual(1.0 - exposure.Result.visible_fraction, exposure.SpanHiddenFractions[0], 1e-12);
            Assert.AreEqual(64, exposure.TriangleVisible.Length);
            Assert.AreEqual(exposure.Result.visible_fraction, exposure.TriangleVisible.Average(), 1e-6,
                            "triangles equal but for the floats of Unity's vertices: the mean of their fractions seen");

            camera.localPosition = new Vector3(0f, (float)Occlusion.EyeHeight, 0.5f);  // 50 cm aside: over the tube's side
            Player.Frame(1f / 60f);
            Assert.AreEqual(1f, exposure.VisibleFraction, "every sight line passes beside the tube");
            Assert.AreEqual(0u, exposure.Result.span_count);

            Exposure handle = exposure.Exposure;
            UnityEngine.Object.Destroy(disk);
            Assert.IsTrue(handle.IsDisposed, "disposed with its component");
        }

        [Test]
        public void AnExposureOnAnOrganFollowsItAndStopsWhenItIsRemoved()
        {
            // A small triangle at the organ's origin, under the tube: hidden; the organ moves 8 cm
            // sideways and takes the target out of the shadow; removed, the component says so.
            EnteronScene scene = NewScene(StraightTube, EnteronScene.Stepping.Manual);
            GameObject patch = Target(scene, "patch", new double[] { -0.001, -0.001, 0, 0.001, -0.001, 0, 0, 0.001, 0 },
                                      new uint[] { 0, 1, 2 });
            patch.transform.localPosition = new Vector3(0.3f, 0f, 0.3f);  // ignored: the mesh is in the organ's frame
            EnteronExposure exposure = patch.AddComponent<EnteronExposure>();
            exposure.obstacle = 0;
            exposure.viewpoint = Camera(scene, new Vector3(0f, (float)Occlusion.EyeHeight, 0f));
            Player.Frame(1f / 60f);
            Assert.AreEqual(0f, exposure.VisibleFraction, "under the tube");

            scene.Drive(s => s.SetObstaclePose(0, new Vec3(0, 0.08, 0), Quat.Identity));
            scene.StepOnce();
            Player.Frame(1f / 60f);
            Assert.AreEqual(1f, exposure.VisibleFraction, "the organ took it out of the shadow");
            Assert.AreEqual(1UL, exposure.Result.steps);

            scene.Drive(s => s.RemoveObstacle(0));
            scene.StepOnce();
            Player.Frame(1f / 60f);
            Assert.IsFalse(exposure.enabled, "a target on a removed organ cannot be measured");
            Assert.IsTrue(Player.Logged.Any(line => line.Contains("obstacle 0 (the target's frame)")),
                          string.Join("\n", Player.Logged.ToArray()));
        }

        [Test]
        public void AnExposureWithoutAViewpointOrATargetSaysSo()
        {
            EnteronScene scene = NewScene(StraightTube, EnteronScene.Stepping.Manual);
            EnteronExposure noTarget = new GameObject("no target").AddComponent<EnteronExposure>();
            noTarget.scene = scene;
            noTarget.viewpoint = scene.transform;
            EnteronExposure noViewpoint = Target(scene, "no viewpoint", new double[] { 0, 0, 0, 0.01, 0, 0, 0, 0.01, 0 },
                                                 new uint[] { 0, 1, 2 }).AddComponent<EnteronExposure>();
            Player.Frame(1f / 60f);
            Assert.IsFalse(noTarget.enabled);
            Assert.IsFalse(noViewpoint.enabled);
            Assert.IsTrue(Player.Logged.Any(line => line.Contains("no target mesh")));
            Assert.IsTrue(Player.Logged.Any(line => line.Contains("no viewpoint")));
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
