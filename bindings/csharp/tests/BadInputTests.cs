// SPDX-License-Identifier: Apache-2.0
// Bad input through the binding (as tests/capi/test_bad_inputs.cpp for C): each row is a
// call that must fail with a status and the library's message naming the bad input,
// change nothing and never crash. Then what the binding itself refuses before C is
// reached (arrays too small for what C would write, closed handles).
using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public unsafe class BadInputTests
    {
        private struct Row
        {
            internal string Name;
            internal Action<Scene> Call;
            internal Status Status;
            internal string Message;  // a part of the library's message
        }

        private static Row R(string name, Status status, string message, Action<Scene> call)
        {
            return new Row { Name = name, Call = call, Status = status, Message = message };
        }

        private static readonly Row[] Rows =
        {
            R("not JSON", Status.Parse, "at byte 15", s => Scene.FromJson("{\"intestine\": ")),
            R("negative radius", Status.InvalidScene, "intestine.radius must be > 0, got -1",
              s => Scene.FromJson("{\"intestine\": {\"radius\": -1}}")),
            R("unknown key", Status.InvalidScene, "lenght", s => Scene.FromJson("{\"intestine\": {\"lenght\": 1}}")),
            R("missing file", Status.InvalidArgument, "no/such/scene.json", s => Scene.FromFile("no/such/scene.json")),
            R("description without struct_size", Status.Version, "struct_size", s => Scene.FromDescription(new SceneDesc())),
            R("three control points", Status.InvalidArgument, "control_points", s =>
            {
                SceneDesc desc = SceneDesc.Default();
                desc.control_points = 3;
                Scene.FromDescription(desc);
            }),
            R("points shape without points", Status.InvalidArgument, "shape_points_xyz_m", s =>
            {
                SceneDesc desc = SceneDesc.Default();
                desc.shape = Shape.Points;
                Scene.FromDescription(desc);
            }),
            R("zero step", Status.InvalidArgument, "dt", s => s.Step(0)),
            R("NaN step", Status.InvalidArgument, "dt", s => s.Step(double.NaN)),
            R("NaN tool position", Status.InvalidArgument, "position", s =>
              s.GetTool(0).SetPose(new Vec3(double.NaN, 0, 0), Quat.Identity)),
            R("zero quaternion", Status.InvalidArgument, "orientation", s =>
              s.GetTool(0).SetPose(Vec3.Zero, new Quat(0, 0, 0, 0))),
            R("unknown tool", Status.NotFound, "7", s => s.GetTool(7)),
            R("unknown effect", Status.NotFound, "99", s => s.GetEffectStats((Effect)99)),
            R("sphere of negative radius", Status.InvalidArgument, "radius must be > 0, got -1", s =>
            {
                ObstacleDesc desc = ObstacleDesc.Default(ObstacleKind.Sphere);
                desc.center_m = new Vec3(0, 1, 1);
                desc.radius_m = -1;
                s.AddObstacle(desc);
            }),
            R("tool of zero radius", Status.InvalidArgument, "radius_m", s =>
            {
                ToolDesc desc = ToolDesc.Default();
                desc.radius_m = 0;
                s.AddTool(desc);
            }),
            R("mesh index out of range", Status.InvalidArgument, "mesh", s =>
              s.AddObstacle(ObstacleDesc.Default(ObstacleKind.Mesh), new double[] { 0, 1, 1, 0, 1.1, 1, 0, 1, 1.1 },
                            new uint[] { 0, 1, 5 })),
            R("unknown obstacle", Status.NotFound, "3", s => s.RemoveObstacle(3)),
            R("not a mesh", Status.InvalidArgument, "not a mesh", s => s.CopyObstacleMesh(0, new double[3], null)),
            R("pin out of range", Status.InvalidArgument, "control_point", s => s.PinPoint(17)),
            R("non-finite gravity", Status.InvalidArgument, "gravity", s => s.SetGravity(new Vec3(0, 0, double.PositiveInfinity))),
            R("not a saved state", Status.InvalidArgument, "", s => s.RestoreState(new byte[64])),
            R("skin with two segments", Status.InvalidArgument, "segments", s =>
            {
                SkinDesc desc = SkinDesc.Default(SkinMethod.Tube);
                desc.segments = 2;
                new Skin(s, desc);
            }),
            R("unknown skin method", Status.InvalidArgument, "method", s =>
            {
                SkinDesc desc = SkinDesc.Default();
                desc.method = (SkinMethod)7;
                new Skin(s, desc);
            }),
            R("exposure without points", Status.InvalidArgument, "desc.points_xyz_m", s =>
              new Exposure(s, ExposureDesc.Default(), new double[0])),
            R("exposure description without struct_size", Status.Version, "ent_exposure_desc.struct_size", s =>
              new Exposure(s, new ExposureDesc(), new double[] { 0, 0, 0 })),
            R("exposure index past the points", Status.InvalidArgument, "desc.triangles[0] has index 5", s =>
              new Exposure(s, ExposureDesc.Default(), new double[] { 0, 0, 0, 0.01, 0, 0, 0, 0.01, 0 }, new uint[] { 0, 1, 5 })),
            R("negative exposure weight", Status.InvalidArgument, "desc.weights[1]", s =>
              new Exposure(s, ExposureDesc.Default(), new double[] { 0, 0, 0, 0.01, 0, 0 }, null, new[] { 1.0, -1.0 })),
            R("zero samples per edge", Status.InvalidArgument, "desc.samples_per_edge", s =>
            {
                ExposureDesc desc = ExposureDesc.Default();
                desc.samples_per_edge = 0;
                new Exposure(s, desc, new double[] { 0, 0, 0, 0.01, 0, 0, 0, 0.01, 0 }, new uint[] { 0, 1, 2 });
            }),
            R("exposure on an unknown obstacle", Status.NotFound, "obstacle 5", s =>
            {
                ExposureDesc desc = ExposureDesc.Default();
                desc.obstacle = 5;
                new Exposure(s, desc, new double[] { 0, 0, 0 });
            }),
            R("non-finite viewpoint", Status.InvalidArgument, "viewpoint_m[2]", s =>
            {
                using (var exposure = new Exposure(s, ExposureDesc.Default(), new double[] { 0, 0, 0 }))
                    exposure.Measure(new Vec3(0, 0, double.NaN));
            }),
        };

        [Test]
        public void EveryBadInputRaisesWithTheLibrarysMessageAndChangesNothing()
        {
            var failures = new List<string>();
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                scene.Step(0.001);
                Stats before = scene.GetStats();
                foreach (Row row in Rows)
                {
                    try
                    {
                        row.Call(scene);
                        failures.Add(row.Name + ": no exception");
                    }
                    catch (EnteronException error)
                    {
                        string line = string.Format("{0}: {1} ({2}) in {3}: \"{4}\"", row.Name, error.Status,
                                                    Library.StatusString(error.Status), error.Function, error.Message);
                        Console.WriteLine(line);
                        if (error.Status != row.Status) failures.Add(line + ", expected " + row.Status);
                        else if (error.Message.IndexOf(row.Message, StringComparison.Ordinal) < 0)
                            failures.Add(line + ", expected a message with \"" + row.Message + "\"");
                        else if (error.Message != Library.LastError)
                            failures.Add(line + ": not ent_last_error's message \"" + Library.LastError + "\"");
                        else if (string.IsNullOrEmpty(error.Message) || string.IsNullOrEmpty(error.Function))
                            failures.Add(line + ": no message or function");
                    }
                    catch (Exception other)
                    {
                        failures.Add(row.Name + ": " + other.GetType().Name + ": " + other.Message);
                    }
                }
                Stats after = scene.GetStats();
                Assert.AreEqual(before.steps, after.steps, "no failed call stepped");
                Assert.AreEqual(1u, after.last_step_attempts, "the appended fields are read: the one step's attempt");
                Assert.AreEqual(before.max_step_ns, after.max_step_ns);
                Assert.AreEqual(before.time_s, after.time_s);
                Assert.AreEqual(1, scene.ObstacleCount, "no obstacle was added");
                Assert.AreEqual(1, scene.ToolCount, "no tool was added");
                scene.Step(0.001);  // and the scene still steps
            }
            Assert.IsEmpty(failures, string.Join("\n", failures.ToArray()));
        }

        [Test]
        public void TheBindingRefusesArraysTooSmallForWhatCWouldWrite()
        {
            using (Scene scene = Scene.FromJson(TestScenes.OnTheFloor))
            {
                Assert.Throws<ArgumentException>(() => scene.Axis(new double[5], 2), "2 points need 6 doubles");
                Assert.Throws<ArgumentOutOfRangeException>(() => scene.Axis(new double[6], -1));
                Assert.Throws<ArgumentNullException>(() => scene.Axis(null));
                Assert.Throws<ArgumentException>(() => scene.ControlPoints(new double[0]), "an empty array is no buffer");
                Assert.AreEqual(Status.BufferTooSmall,
                                Assert.Throws<EnteronException>(() => scene.ControlPoints(new double[3 * 16])).Status);
                int organ = scene.AddObstacle(ObstacleDesc.Default(ObstacleKind.Mesh),
                                              new double[] { 0, 0.3, 0.1, 0.05, 0.3, 0.1, 0, 0.35, 0.1, 0, 0.3, 0.15 },
                                              new uint[] { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 });
                Assert.Throws<ArgumentException>(() => scene.CopyObstacleMesh(organ, new double[0], null),
                                                 "an empty array is no buffer");
                Assert.AreEqual(Status.BufferTooSmall,
                                Assert.Throws<EnteronException>(() => scene.CopyObstacleMesh(organ, new double[9], null)).Status);
                Assert.Throws<ArgumentOutOfRangeException>(() => scene.PinPoint(-1));
                Assert.Throws<ArgumentException>(() => Scene.FromDescription(SceneDesc.Default(), new double[4]),
                                                 "points come in triples");
                Assert.Throws<ArgumentNullException>(() => Scene.FromJson(null));
                Assert.Throws<ArgumentException>(() => Scene.FromJson(TestScenes.Minimal,
                    new Callbacks { Log = (level, message) => { }, NativeUserData = (IntPtr)1 }));
                double[] ranges = null;
                Assert.DoesNotThrow(() => scene.GetTool(0).ReadContacts(ranges));

                var patch = new double[] { 0, 0, 0, 0.01, 0, 0, 0, 0.01, 0 };
                var triangle = new uint[] { 0, 1, 2 };
                Assert.Throws<ArgumentException>(() => new Exposure(scene, ExposureDesc.Default(), new double[4]),
                                                 "points come in triples");
                Assert.Throws<ArgumentException>(() => new Exposure(scene, ExposureDesc.Default(), patch, new uint[] { 0, 1 }),
                                                 "triangles come in triples");
                Assert.Throws<ArgumentException>(() => new Exposure(scene, ExposureDesc.Default(), patch, triangle, new double[3]),
                                                 "one weight per triangle: C would read past two");
                Assert.Throws<ArgumentNullException>(() => new Exposure(scene, ExposureDesc.Default(), null));
                Assert.Throws<ArgumentNullException>(() => new Exposure(null, ExposureDesc.Default(), patch));
                var exposure = new Exposure(scene, ExposureDesc.Default(), patch);
                Assert.Throws<ArgumentException>(() => exposure.Measure(Vec3.Zero, null, null, null, new double[2]),
                                                 "three points need three fractions seen");
                Assert.Throws<ArgumentException>(() => exposure.Measure(Vec3.Zero, new double[8], new double[3]),
                                                 "four spans need four hidden fractions");
                Assert.Throws<ArgumentException>(() => exposure.Measure(Vec3.Zero, new double[8], null, new int[3]),
                                                 "four spans need four tubes");
                Assert.Throws<ArgumentException>(() => exposure.Measure(Vec3.Zero, null, new double[4]),
                                                 "the spans' capacity is spansU's");
                Assert.DoesNotThrow(() => exposure.Measure(Vec3.Zero, new double[8], new double[4], new int[4], new double[3]));
                Assert.DoesNotThrow(() => exposure.Measure(Vec3.Zero, new double[0], new double[0], null, null));
                exposure.Dispose();
                Assert.Throws<ObjectDisposedException>(() => exposure.Measure(Vec3.Zero));
            }
        }

        [Test]
        public void EveryStatusHasTheLibrarysText()
        {
            foreach (Status status in Enum.GetValues(typeof(Status)))
                Assert.IsNotEmpty(Library.StatusString(status));
            Assert.AreEqual("ok", Library.StatusString(Status.Ok));
            Assert.AreEqual("unknown status", Library.StatusString((Status)1000));
        }
    }
}
