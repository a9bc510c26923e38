// SPDX-License-Identifier: Apache-2.0
// The thread model of C through the binding: a physics thread steps at 1 kHz, a haptic
// thread posts poses and reads the force at 1 kHz, a render thread updates a skin at 60 Hz;
// then the scene is disposed under the stepping thread. And the misuses C leaves to the
// caller, which the binding turns into exceptions: a dispose racing a step, two drivers,
// two threads on one skin.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Threading;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public class ThreadTests
    {
        /// <summary>Runs body every period on this thread until stop is set, on an absolute schedule.</summary>
        private static void Paced(TimeSpan period, Func<bool> stop, Action body)
        {
            var clock = Stopwatch.StartNew();
            long next = 0;
            long ticks = (long)(period.TotalSeconds * Stopwatch.Frequency);
            while (!stop())
            {
                body();
                next += ticks;
                long late = clock.ElapsedTicks - next;
                if (late > 10 * ticks) next = clock.ElapsedTicks;  // overloaded: restart the schedule, no burst
                while (clock.ElapsedTicks < next)
                {
                    if (next - clock.ElapsedTicks > Stopwatch.Frequency / 500) Thread.Sleep(1);
                    else Thread.SpinWait(50);
                }
            }
        }

        private sealed class Worker
        {
            private readonly Thread _thread;
            internal Exception Ended;  // what ended its loop (null: it was stopped)
            internal volatile bool Stop;
            internal int Iterations;

            internal Worker(string name, Action<Worker> loop)
            {
                _thread = new Thread(() =>
                {
                    try
                    {
                        loop(this);
                    }
                    catch (Exception error)
                    {
                        Ended = error;
                    }
                }) { Name = name, IsBackground = true };
                _thread.Start();
            }

            internal void Join()
            {
                Assert.IsTrue(_thread.Join(TimeSpan.FromSeconds(30)), _thread.Name + " did not end");
            }
        }

        [Test]
        public void PhysicsHapticAndRenderThreadsThenADisposeUnderTheStep()
        {
            Scene scene = Scene.FromJson(TestScenes.OnTheFloor);
            Tool tool = scene.GetTool(0);
            var problems = new List<string>();
            using (var skin = new Skin(scene, SkinDesc.Default()))
            {
                var physics = new Worker("physics", w => Paced(TimeSpan.FromMilliseconds(1), () => w.Stop, () =>
                {
                    scene.Step(0.001);
                    ++w.Iterations;
                }));
                var haptic = new Worker("haptic", w =>
                {
                    ulong lastSteps = 0;
                    var feedback = new ToolFeedback();
                    Paced(TimeSpan.FromMilliseconds(1), () => w.Stop, () =>
                    {
                        double y = 0.05 - 0.05 * Math.Sin(++w.Iterations * 2e-3);
                        tool.SetPose(new Vec3(0, y, TestScenes.Radius), Quat.Identity);
                        if (w.Iterations % 400 == 100) tool.Grasp();
                        if (w.Iterations % 400 == 300) tool.Release();
                        tool.ReadFeedback(ref feedback);
                        if (feedback.force_N.Length > TestScenes.MaxForce * (1 + 1e-12))
                            lock (problems) problems.Add("haptic: |F| " + feedback.force_N.Length + " above max_force");
                        if (feedback.steps < lastSteps)
                            lock (problems) problems.Add("haptic: the feedback went back in time");
                        lastSteps = feedback.steps;
                    });
                });
                double lastTime = -1;
                int framesAfterDispose = 0;
                var render = new Worker("render", w => Paced(TimeSpan.FromMilliseconds(1000.0 / 60), () => w.Stop, () =>
                {
                    skin.Update();
                    MeshInfo mesh = skin.Mesh;
                    var positions = new float[3 * mesh.VertexCount];  // a renderer would keep its arrays
                    skin.CopyPositions(positions);
                    foreach (float x in positions)
                        if (float.IsNaN(x) || float.IsInfinity(x))
                            lock (problems) problems.Add("render: a vertex is not finite");
                    if (mesh.TimeSeconds < lastTime) lock (problems) problems.Add("render: the mesh went back in time");
                    lastTime = mesh.TimeSeconds;
                    ++w.Iterations;
                    if (scene.IsDisposed) ++framesAfterDispose;
                }));

                Thread.Sleep(1500);
                scene.Dispose();  // under the physics and haptic threads' calls
                physics.Join();
                haptic.Join();
                while (framesAfterDispose < 3) Thread.Sleep(20);  // the skin outlives its scene
                render.Stop = true;
                render.Join();

                Console.WriteLine("threads: physics {0} steps, haptic {1} ticks, render {2} frames in 1.5 s; " +
                                  "after the dispose: physics {3}, haptic {4}, render {5} more frames",
                                  physics.Iterations, haptic.Iterations, render.Iterations,
                                  physics.Ended == null ? "-" : physics.Ended.GetType().Name,
                                  haptic.Ended == null ? "-" : haptic.Ended.GetType().Name, framesAfterDispose);
                Assert.IsEmpty(problems, string.Join("\n", problems.ToArray()));
                Assert.IsInstanceOf<ObjectDisposedException>(physics.Ended, "the stepping thread is told, not crashed");
                Assert.IsInstanceOf<ObjectDisposedException>(haptic.Ended, "the haptic thread is told, not crashed");
                Assert.IsNull(render.Ended, render.Ended == null ? "" : render.Ended.ToString());
                Assert.Greater(physics.Iterations, 150, "the physics thread stepped (at most 1500)");
                Assert.Greater(haptic.Iterations, 150);
                Assert.Greater(render.Iterations, 15);
                Assert.AreEqual(0.001 * physics.Iterations, lastTime, 1e-9, "the skin shows the last step published");
            }
        }

        [Test]
        public void ADisposeRacingTheStepAndTheQueriesNeverCrashes()
        {
            var random = new Random(34);
            int disposedWhileStepping = 0;
            for (int round = 0; round < 100; ++round)
            {
                Scene scene = Scene.FromJson(TestScenes.OnTheFloor);
                Tool tool = scene.GetTool(0);
                var stepping = new Worker("stepping", w => { for (;;) { scene.Step(0.001); ++w.Iterations; } });
                var reading = new Worker("reading", w =>
                {
                    var axis = new double[30];
                    for (;;)
                    {
                        scene.Axis(axis);
                        tool.ReadFeedback();
                        tool.SetPose(new Vec3(0, 0.04, TestScenes.Radius), Quat.Identity);
                        ++w.Iterations;
                    }
                });
                Thread.Sleep(random.Next(0, 3));
                scene.Dispose();
                stepping.Join();
                reading.Join();
                Assert.IsInstanceOf<ObjectDisposedException>(stepping.Ended, "round " + round + ": " + stepping.Ended);
                Assert.IsInstanceOf<ObjectDisposedException>(reading.Ended, "round " + round + ": " + reading.Ended);
                if (stepping.Iterations > 0) ++disposedWhileStepping;
            }
            Console.WriteLine("dispose under a stepping thread: {0} of 100 rounds after at least one step", disposedWhileStepping);
            Assert.Greater(disposedWhileStepping, 0);
        }

        [Test]
        public void ADisposeRacingAnExposureQueryNeverCrashes()
        {
            // Even rounds dispose the scene under the query, odd ones the exposure; a query
            // of 4096 sight lines takes long enough for most disposes to land during one.
            double[] points;
            uint[] triangles;
            Occlusion.Disk(0.0, Occlusion.BandHalfWidth(), 0.01, out points, out triangles);
            ExposureDesc desc = ExposureDesc.Default();
            desc.samples_per_edge = 8;
            var random = new Random(29);
            int roundsWithAQuery = 0;
            for (int round = 0; round < 100; ++round)
            {
                Scene scene = Occlusion.StraightTube();
                var exposure = new Exposure(scene, desc, points, triangles);
                var measuring = new Worker("measuring", w =>
                {
                    var spans = new double[16];
                    var seen = new double[exposure.ElementCount];
                    for (;;)
                    {
                        double visible = exposure.Measure(Occlusion.Eye, spans, null, null, seen).visible_fraction;
                        if (Math.Abs(visible - 0.5) > 0.01) throw new InvalidOperationException("visible " + visible);
                        ++w.Iterations;
                    }
                });
                Thread.Sleep(random.Next(0, 3));
                if (round % 2 == 0) scene.Dispose();
                else exposure.Dispose();
                measuring.Join();
                Assert.IsInstanceOf<ObjectDisposedException>(measuring.Ended, "round " + round + ": " + measuring.Ended);
                if (measuring.Iterations > 0) ++roundsWithAQuery;
                exposure.Dispose();  // after its scene, or again
                scene.Dispose();
            }
            Console.WriteLine("dispose under a measuring thread: {0} of 100 rounds after at least one query", roundsWithAQuery);
            Assert.Greater(roundsWithAQuery, 0);
        }

        [Test]
        public void TwoThreadsMeasuringOneExposureWhileTheSceneStepsAreToldBusy()
        {
            // A tube falling onto the floor over a disk: each query sees one whole published
            // state (its fraction in [0, 1], its steps never going back); a query on the
            // exposure another thread is measuring gets the library's Busy and writes nothing.
            using (Scene scene = Occlusion.StraightTube(SceneDesc.Default().effects))
            {
                scene.AddObstacle(ObstacleDesc.Default(ObstacleKind.Plane));  // the floor z = 0, under the disk's plane
                double[] points;
                uint[] triangles;
                Occlusion.Disk(0.0, 0.0, 0.02, out points, out triangles);
                using (var exposure = new Exposure(scene, ExposureDesc.Default(), points, triangles))
                {
                    int busy = 0;
                    var problems = new List<string>();
                    var deadline = Stopwatch.StartNew();
                    var physics = new Worker("physics", w =>
                    {
                        while (!w.Stop)
                        {
                            scene.Step(0.001);
                            ++w.Iterations;
                        }
                    });
                    Action<Worker> measure = w =>
                    {
                        ulong lastSteps = 0;
                        var seen = new double[exposure.ElementCount];
                        while (deadline.Elapsed < TimeSpan.FromSeconds(10) && (Volatile.Read(ref busy) == 0 || w.Iterations < 100))
                        {
                            seen[0] = -7.0;
                            try
                            {
                                ExposureResult r = exposure.Measure(Occlusion.Eye, null, null, null, seen);
                                if (!(r.visible_fraction >= 0.0 && r.visible_fraction <= 1.0) || r.steps < lastSteps || seen[0] < 0.0)
                                    lock (problems) problems.Add(w.Iterations + ": visible " + r.visible_fraction + ", steps " + r.steps);
                                lastSteps = r.steps;
                                ++w.Iterations;
                            }
                            catch (EnteronException error)
                            {
                                if (error.Status != Status.Busy) throw;
                                if (seen[0] != -7.0) lock (problems) problems.Add("a busy query wrote into the array");
                                Interlocked.Increment(ref busy);
                            }
                        }
                    };
                    var first = new Worker("first measurer", measure);
                    var second = new Worker("second measurer", measure);
                    first.Join();
                    second.Join();
                    physics.Stop = true;
                    physics.Join();
                    Console.WriteLine("two threads on one exposure while {0} steps: {1} + {2} queries, {3} refused as busy",
                                      physics.Iterations, first.Iterations, second.Iterations, busy);
                    Assert.IsNull(first.Ended, first.Ended == null ? "" : first.Ended.ToString());
                    Assert.IsNull(second.Ended, second.Ended == null ? "" : second.Ended.ToString());
                    Assert.IsNull(physics.Ended, physics.Ended == null ? "" : physics.Ended.ToString());
                    Assert.IsEmpty(problems, string.Join("\n", problems.ToArray()));
                    Assert.Greater(busy, 0, "the two threads overlapped at least once in 10 s");
                    Assert.Greater(physics.Iterations, 0);
                }
            }
        }

        [Test]
        public void OfTwoDriversOneIsToldBusyAndNothingIsLost()
        {
            using (Scene scene = Scene.FromJson(TestScenes.Minimal))
            {
                int busy = 0;
                var deadline = Stopwatch.StartNew();
                Action<Worker> drive = w =>
                {
                    while (deadline.Elapsed < TimeSpan.FromSeconds(10) && (Volatile.Read(ref busy) == 0 || w.Iterations < 500))
                    {
                        try
                        {
                            scene.Step(0.0001);
                            ++w.Iterations;
                        }
                        catch (EnteronException error)
                        {
                            if (error.Status != Status.Busy) throw;
                            Interlocked.Increment(ref busy);
                        }
                    }
                };
                var first = new Worker("first driver", drive);
                var second = new Worker("second driver", drive);
                first.Join();
                second.Join();
                Assert.IsNull(first.Ended);
                Assert.IsNull(second.Ended);
                Console.WriteLine("two drivers: {0} + {1} steps, {2} refused as busy", first.Iterations, second.Iterations, busy);
                Assert.Greater(busy, 0, "the two drivers overlapped at least once in 10 s");
                Assert.AreEqual((ulong)(first.Iterations + second.Iterations), scene.GetStats().steps,
                                "every step that was not refused counted once");
            }
        }

        [Test]
        public void ASkinUsedByTwoThreadsAtOnceIsRefused()
        {
            using (Scene scene = Scene.FromJson(TestScenes.Minimal))
            using (var skin = new Skin(scene, SkinDesc.Default()))
            {
                int refused = 0;
                var deadline = Stopwatch.StartNew();
                Action<Worker> update = w =>
                {
                    while (deadline.Elapsed < TimeSpan.FromSeconds(10) && Volatile.Read(ref refused) == 0)
                    {
                        try
                        {
                            skin.Update();
                            ++w.Iterations;
                        }
                        catch (InvalidOperationException)
                        {
                            Interlocked.Increment(ref refused);
                        }
                    }
                };
                var a = new Worker("skin user a", update);
                var b = new Worker("skin user b", update);
                a.Join();
                b.Join();
                Assert.IsNull(a.Ended);
                Assert.IsNull(b.Ended);
                Assert.Greater(refused, 0, "the two threads overlapped at least once in 10 s");
                Assert.AreEqual((ulong)(a.Iterations + b.Iterations), skin.Mesh.Updates);
            }
        }
    }
}
