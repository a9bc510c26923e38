// SPDX-License-Identifier: Apache-2.0
// Scenes made every way the C API offers (JSON text, a JSON file, a C description), their
// queries, obstacles and run-time changes, through the binding.
using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public class SceneTests
    {
        [Test]
        public void TheLoadedLibraryIsTheVersionThisBindingSpeaks()
        {
            Assert.AreEqual(Library.SupportedMajor, (int)(Library.Version >> 16));
            StringAssert.IsMatch(@"^\d+\.\d+\.\d+$", Library.VersionString);
            Library.EnsureCompatible();
        }

        [Test]
        public void AJsonSceneStepsAndIsQueried()
        {
            using (Scene scene = Scene.FromJson(TestScenes.Minimal))
            {
                Assert.AreEqual(40, scene.ControlPointCount);
                for (int i = 0; i < 100; ++i) scene.Step(0.001);
                Stats stats = scene.GetStats();
                Assert.AreEqual(100UL, stats.steps);
                Assert.AreEqual(0.1, stats.time_s, 1e-12);
                Assert.AreEqual(40U, stats.control_points);
                Assert.Greater(stats.kinetic_energy_J, 0.0, "it falls");

                var points = new double[40 * 3];
                Assert.AreEqual(40, scene.ControlPoints(points));
                var axis = new double[10 * 3];
                scene.Axis(axis);
                // The spline passes through its control points: the axis starts and ends at the first and last.
                for (int k = 0; k < 3; ++k)
                {
                    Assert.AreEqual(points[k], axis[k], 1e-12);
                    Assert.AreEqual(points[39 * 3 + k], axis[9 * 3 + k], 1e-12);
                }

                EffectStats gravity = scene.GetEffectStats(Effect.Gravity);
                Assert.AreEqual(1, gravity.enabled);
                Assert.Greater(gravity.calls, 0UL);
                EffectStats pinned = scene.GetEffectStats(Effect.Pinned);
                Assert.AreEqual(0, pinned.enabled, "an effect the scene does not name does not run");
                Assert.AreEqual(0UL, pinned.calls);
                Assert.AreEqual("gravity", Library.EffectName(Effect.Gravity));
                Assert.IsNull(Library.EffectName((Effect)99));
            }
        }

        [Test]
        public void TheDefaultDescriptionIsTheHeadersDefaults()
        {
            SceneDesc desc = SceneDesc.Default();
            Assert.AreEqual(Effects.Stretch | Effects.Bend | Effects.Damping | Effects.Gravity, desc.effects);
            Assert.AreEqual(6.0, desc.length_m);
            Assert.AreEqual(0.0125, desc.radius_m);
            Assert.AreEqual(240U, desc.control_points);
            Assert.AreEqual(Shape.Helix, desc.shape);
            Assert.AreEqual(Integrator.ImplicitEuler, desc.integrator);
            Assert.AreEqual(new Vec3(0, 0, -9.81), desc.gravity_m_per_s2);
            Assert.AreEqual(PinnedEnds.None, desc.clamped_ends);
            ToolDesc tool = ToolDesc.Default();
            Assert.AreEqual(5.0, tool.max_force_N);
            Assert.AreEqual(ToolMode.Proxy, tool.mode);
            Assert.AreEqual(1.0, tool.orientation_wxyz.W);
            SkinDesc skin = SkinDesc.Default();
            Assert.AreEqual(SkinMethod.Convolution, skin.method);
            Assert.AreEqual(16U, skin.segments);
            Assert.AreEqual(1, skin.stable_topology);
            ObstacleDesc obstacle = ObstacleDesc.Default(ObstacleKind.Sphere);
            Assert.AreEqual(ObstacleKind.Sphere, obstacle.kind);
            Assert.AreEqual(0.05, obstacle.radius_m);
            Assert.AreEqual(-1.0, obstacle.friction);
        }

        [Test]
        public void ADescriptionAndItsJsonRunTheSameBits()
        {
            // The JSON and the C description share their defaults (docs/scene-json.md); the
            // C one also turns gravity and damping on, which the JSON names.
            SceneDesc desc = SceneDesc.Default();
            desc.length_m = 1.0;
            desc.control_points = 40;
            const string json = "{\"intestine\": {\"length\": 1.0, \"control_points\": 40}," +
                                " \"gravity\": [0, 0, -9.81], \"damping\": {}}";
            using (Scene fromDescription = Scene.FromDescription(desc))
            using (Scene fromJson = Scene.FromJson(json))
            {
                for (int i = 0; i < 200; ++i)
                {
                    fromDescription.Step(0.001);
                    fromJson.Step(0.001);
                }
                var a = new double[40 * 3];
                var b = new double[40 * 3];
                fromDescription.ControlPoints(a);
                fromJson.ControlPoints(b);
                Bits.AssertSame(a, b, "control points after 0.2 s");
                // Each reads back the description it was made from (ent_scene_read_desc).
                SceneDesc read = fromJson.ReadDescription();
                Assert.AreEqual(1.0, read.length_m);
                Assert.AreEqual(40U, read.control_points);
                Assert.AreEqual(desc.radius_m, fromDescription.ReadDescription().radius_m);
            }
        }

        [Test]
        public void ADescriptionTakesItsPointsAndPins()
        {
            SceneDesc desc = SceneDesc.Default();
            desc.effects = Effects.Stretch | Effects.Bend | Effects.Gravity | Effects.Damping | Effects.Pinned;
            var points = new double[8 * 3];
            for (int i = 0; i < 8; ++i) points[3 * i] = 0.05 * i;  // a straight 35 cm bowel along x
            using (Scene scene = Scene.FromDescription(desc, points, new uint[] { 0, 7 }))
            {
                Assert.AreEqual(8, scene.ControlPointCount);
                for (int i = 0; i < 300; ++i) scene.Step(0.001);
                var now = new double[8 * 3];
                scene.ControlPoints(now);
                for (int k = 0; k < 3; ++k)
                {
                    Assert.AreEqual(points[k], now[k], 1e-12, "the pinned first point stays");
                    Assert.AreEqual(points[21 + k], now[21 + k], 1e-12, "the pinned last point stays");
                }
                Assert.Less(now[3 * 4 + 2], -1e-3, "the middle sags under gravity");
            }
        }

        [Test]
        public void TheLogHandlerHearsTheLibrarysWarnings()
        {
            var lines = new List<string>();
            var callbacks = new Callbacks { Log = (level, message) => { if (level >= LogLevel.Warning) lines.Add(message); } };
            // 1000 times Earth's gravity: accepted, with a warning naming the field.
            const string json = "{\"intestine\": {\"length\": 0.5, \"control_points\": 20}, \"gravity\": [0, 0, -9810]}";
            using (Scene scene = Scene.FromJson(json, callbacks)) scene.Step(0.001);
            Assert.IsNotEmpty(lines);
            StringAssert.Contains("gravity", string.Join("\n", lines.ToArray()));
        }

        [Test]
        public void TheAbdomenFileFindsItsOrganMeshes()
        {
            using (Scene scene = Scene.FromFile(TestPaths.Source("examples/scenes/abdomen.json")))
            {
                Assert.AreEqual(3, scene.ObstacleCount);
                Assert.AreEqual(1, scene.ToolCount);
                Vec3 position;
                Quat orientation;
                scene.GetObstaclePose(1, out position, out orientation);  // the liver
                Assert.AreEqual(new Vec3(0.065, 0.165, -0.03), position);
                int vertices, triangles;
                scene.GetObstacleMeshCounts(1, out vertices, out triangles);
                Assert.Greater(vertices, 3);
                Assert.Greater(triangles, 3);
                var xyz = new double[3 * vertices];
                var indices = new uint[3 * triangles];
                scene.CopyObstacleMesh(1, xyz, indices);
                foreach (uint index in indices) Assert.Less(index, (uint)vertices);
                scene.Step(0.001);
                Assert.AreEqual(1UL, scene.GetStats().steps);
            }
        }

        [Test]
        public void ObstaclesAreAddedMovedAndRemoved()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                Assert.AreEqual(1, scene.ObstacleCount);
                // A tetrahedron (an organ) far from the bowel, from arrays.
                var vertices = new double[] { 0, 0.3, 0.1, 0.05, 0.3, 0.1, 0, 0.35, 0.1, 0, 0.3, 0.15 };
                var triangles = new uint[] { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
                int organ = scene.AddObstacle(ObstacleDesc.Default(ObstacleKind.Mesh), vertices, triangles);
                Assert.AreEqual(1, organ);
                int sphere;
                {
                    ObstacleDesc desc = ObstacleDesc.Default(ObstacleKind.Sphere);
                    desc.center_m = new Vec3(0, -0.3, 0.1);
                    desc.radius_m = 0.02;
                    sphere = scene.AddObstacle(desc);
                }
                Assert.AreEqual(3, scene.ObstacleCount);
                int vertexCount, triangleCount;
                scene.GetObstacleMeshCounts(organ, out vertexCount, out triangleCount);
                Assert.AreEqual(4, vertexCount);
                Assert.AreEqual(4, triangleCount);
                var copied = new double[12];
                var copiedTriangles = new uint[12];
                scene.CopyObstacleMesh(organ, copied, copiedTriangles);
                Bits.AssertSame(vertices, copied, "the mesh as the obstacle holds it");

                scene.SetObstaclePose(sphere, new Vec3(0, 0.01, 0), new Quat(1, 0, 0, 0));
                scene.SetObstacleVelocity(sphere, new Vec3(0, 1e-3, 0), Vec3.Zero);
                scene.SetObstacleFriction(sphere, 0.1);
                scene.Step(0.001);
                Vec3 position;
                Quat orientation;
                scene.GetObstaclePose(sphere, out position, out orientation);
                Assert.AreEqual(0.01, position.Y, 1e-15, "the pose is reached at the end of the step");
                scene.RemoveObstacle(sphere);
                scene.Step(0.001);
                Assert.AreEqual(2, scene.ObstacleCount);
                var error = Assert.Throws<EnteronException>(() => scene.GetObstaclePose(sphere, out position, out orientation));
                Assert.AreEqual(Status.NotFound, error.Status);
            }
        }

        [Test]
        public void GravityPinsAndTheMesenteryChangeBetweenSteps()
        {
            using (Scene scene = Scene.FromJson(TestScenes.Minimal))
            {
                scene.Step(0.001);
                scene.SetGravity(Vec3.Zero);
                scene.PinPoint(20);
                var before = new double[40 * 3];
                scene.ControlPoints(before);
                for (int i = 0; i < 50; ++i) scene.Step(0.001);
                var after = new double[40 * 3];
                scene.ControlPoints(after);
                for (int k = 0; k < 3; ++k) Assert.AreEqual(before[60 + k], after[60 + k], 1e-12, "the pinned point stays");
                scene.UnpinPoint(20);
                scene.AttachMesentery();
                Assert.AreEqual(Status.NotFound,
                                Assert.Throws<EnteronException>(() => scene.UnpinPoint(20)).Status, "no longer pinned");
                Assert.AreEqual(Status.NotFound,
                                Assert.Throws<EnteronException>(() => scene.AttachClampedEnd(PinnedEnds.First)).Status,
                                "no clamped end");
                scene.Step(0.001);
            }
        }

        [Test]
        public void DisposeIsIdempotentAndLaterCallsThrow()
        {
            Scene scene = Scene.FromJson(TestScenes.Minimal);
            Assert.IsFalse(scene.IsDisposed);
            scene.Dispose();
            scene.Dispose();
            Assert.IsTrue(scene.IsDisposed);
            Assert.Throws<ObjectDisposedException>(() => scene.Step(0.001));
            Assert.Throws<ObjectDisposedException>(() => scene.GetStats());
            Assert.Throws<ObjectDisposedException>(() => scene.Axis(new double[30]));
        }
    }
}
