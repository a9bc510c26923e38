// SPDX-License-Identifier: Apache-2.0
// Exposure through the binding against analytic occlusion, as tests/capi/test_exposure.cpp
// (TestSupport.cs, Occlusion): a straight tube over the plane z = 0 hides exactly the band
// its sight lines graze; a disk on the band's edge is half seen, one inside it not seen, one
// beyond it fully seen. Then weights, a target on an obstacle, and what a failed query
// leaves in the caller's arrays. Bad input is in BadInputTests, allocations in
// NoGcAllocationTests, threads in ThreadTests.
using System;
using System.Linq;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public class ExposureTests
    {
        private const int Capacity = 16;  // spans

        [Test]
        public void EachPointIsHiddenExactlyWhereTheAnalyticBandSays()
        {
            using (Scene scene = Occlusion.StraightTube())
            {
                var grid = new double[3 * 21 * 81];  // across the band and beyond it
                int n = 0;
                for (int i = -10; i <= 10; ++i)
                    for (int j = -40; j <= 40; ++j, ++n)
                    {
                        grid[3 * n] = 0.004 * i;
                        grid[3 * n + 1] = 0.001 * j + 0.00037;
                    }
                using (var exposure = new Exposure(scene, ExposureDesc.Default(), grid))
                {
                    Assert.AreEqual(n, exposure.ElementCount, "no triangles: each point is an element");
                    var seen = new double[n];
                    ExposureResult result = exposure.Measure(Occlusion.Eye, null, null, null, seen);
                    int hidden = 0;
                    for (int k = 0; k < n; ++k)
                    {
                        bool analytic = Occlusion.Hidden(grid[3 * k + 1]);
                        Assert.AreEqual(analytic ? 0.0 : 1.0, seen[k], "point ({0}, {1})", grid[3 * k], grid[3 * k + 1]);
                        hidden += analytic ? 1 : 0;
                    }
                    Assert.Greater(hidden, 0);
                    Assert.AreEqual((uint)n, result.samples);
                    Assert.AreEqual((uint)hidden, result.hidden_samples);
                    Assert.AreEqual(1.0 - (double)hidden / n, result.visible_fraction, 1e-12);
                }
            }
        }

        [Test]
        public void ADiskOnTheBandsEdgeIsHalfCoveredInsideItFullyBeyondItNot()
        {
            double w = Occlusion.BandHalfWidth();
            const double rho = 0.01;
            var cases = new[]
            {
                new { Name = "half covered", CenterY = w, Expected = 0.5 },
                new { Name = "fully covered", CenterY = 0.0, Expected = 0.0 },
                new { Name = "not covered", CenterY = w + rho + 0.003, Expected = 1.0 },
            };
            using (Scene scene = Occlusion.StraightTube())
            {
                foreach (var c in cases)
                {
                    double[] points;
                    uint[] triangles;
                    Occlusion.Disk(0.0, c.CenterY, rho, out points, out triangles);
                    ExposureDesc desc = ExposureDesc.Default();
                    desc.samples_per_edge = 8;
                    using (var exposure = new Exposure(scene, desc, points, triangles))
                    {
                        Assert.AreEqual(64, exposure.ElementCount, "a patch: each triangle is an element");
                        var spans = Filled(2 * Capacity);
                        var fractions = Filled(Capacity);
                        var tubes = new int[Capacity];
                        var seen = Filled(exposure.ElementCount);
                        ExposureResult r = exposure.Measure(Occlusion.Eye, spans, fractions, tubes, seen);
                        Console.WriteLine("{0}: visible {1:F4} (analytic {2:F1}), {3} spans", c.Name, r.visible_fraction,
                                          c.Expected, r.span_count);
                        Assert.AreEqual(c.Expected, r.visible_fraction, 0.01, c.Name);
                        Assert.AreEqual(64u * 64u, r.samples, c.Name);
                        // The fan's triangles have one area and one sample count: the mean of their
                        // fractions seen is the visible fraction.
                        Assert.AreEqual(r.visible_fraction, seen.Average(), 1e-12, c.Name + ": elementVisible");
                        Assert.IsTrue(seen.All(f => f >= 0.0 && f <= 1.0), c.Name);

                        ExposureResult bare = exposure.Measure(Occlusion.Eye);
                        Assert.AreEqual(r.visible_fraction, bare.visible_fraction, c.Name + ": the same without arrays");
                        Assert.AreEqual(r.span_count, bare.span_count, c.Name);

                        if (c.Expected == 1.0)
                        {
                            Assert.AreEqual(0u, r.span_count, c.Name);
                            Assert.AreEqual(-7.0, spans[0], c.Name + ": no span written");
                            continue;
                        }
                        // One span around the disk's shadow on the axis: sight lines to x in
                        // [-rho, rho] cross the axis' height at x (H - h) / H; the span reaches R
                        // (plus a chord of 6 mm) beyond.
                        Assert.AreEqual(1u, r.span_count, c.Name);
                        Assert.AreEqual(0, tubes[0], c.Name);
                        double reach = rho * (Occlusion.EyeHeight - Occlusion.AxisHeight) / Occlusion.EyeHeight;
                        double length = Occlusion.TubeLength, slack = (TestScenes.Radius + 0.0065) / length;
                        Assert.LessOrEqual(spans[0], 0.5 - reach / length + 1e-9, c.Name);
                        Assert.GreaterOrEqual(spans[0], 0.5 - reach / length - slack, c.Name);
                        Assert.GreaterOrEqual(spans[1], 0.5 + reach / length - 1e-9, c.Name);
                        Assert.LessOrEqual(spans[1], 0.5 + reach / length + slack, c.Name);
                        Assert.AreEqual(1.0 - r.visible_fraction, fractions[0], 1e-12, c.Name);
                        Assert.AreEqual(-7.0, spans[2], c.Name + ": one span, nothing written past it");
                    }
                }
            }
        }

        [Test]
        public void WeightsCountAndAWeightlessPointCountsForNothing()
        {
            using (Scene scene = Occlusion.StraightTube())
            using (var exposure = new Exposure(scene, ExposureDesc.Default(),
                                               new double[] { 0, 0, 0, 0, 0.05, 0, 0, -0.05, 0 },  // hidden, seen, seen
                                               null, new[] { 3.0, 1.0, 0.0 }))
            {
                ExposureResult r = exposure.Measure(Occlusion.Eye);
                Assert.AreEqual(0.25, r.visible_fraction, 1e-15);
                Assert.AreEqual(1u, r.hidden_samples);
            }
        }

        [Test]
        public void ATargetOnAnObstacleMovesWithItAndARemovedOneIsRefused()
        {
            using (Scene scene = Occlusion.StraightTube())
            {
                ObstacleDesc plane = ObstacleDesc.Default(ObstacleKind.Plane);
                plane.center_m = new Vec3(0, 0, -0.1);
                int organ = scene.AddObstacle(plane);
                ExposureDesc desc = ExposureDesc.Default();
                desc.obstacle = organ;
                using (var exposure = new Exposure(scene, desc, new double[] { 0, 0, 0 }))  // its origin: under the tube
                {
                    Assert.AreEqual(0.0, exposure.Measure(Occlusion.Eye).visible_fraction);
                    scene.SetObstaclePose(organ, new Vec3(0, 0.08, 0), Quat.Identity);  // 8 cm sideways, out of the shadow
                    scene.Step(0.001);
                    ExposureResult moved = exposure.Measure(Occlusion.Eye);
                    Assert.AreEqual(1.0, moved.visible_fraction);
                    Assert.AreEqual(1UL, moved.steps);
                    Assert.AreEqual(0.001, moved.time_s, 1e-15);

                    scene.RemoveObstacle(organ);
                    scene.Step(0.001);
                    var spans = Filled(2 * Capacity);
                    var seen = Filled(1);
                    var error = Assert.Throws<EnteronException>(() => exposure.Measure(Occlusion.Eye, spans, null, null, seen));
                    Assert.AreEqual(Status.NotFound, error.Status);
                    Assert.AreEqual("ent_scene_exposure", error.Function);
                    StringAssert.Contains("obstacle " + organ + " (the target's frame)", error.Message);
                    Assert.IsTrue(spans.All(x => x == -7.0) && seen[0] == -7.0, "nothing written on failure");
                }
            }
        }

        [Test]
        public void AnExposureOutlivesItsSceneButMeasuresOnlyWhileItLives()
        {
            Scene scene = Occlusion.StraightTube();
            var exposure = new Exposure(scene, ExposureDesc.Default(), new double[] { 0, 0, 0 });
            Assert.AreSame(scene, exposure.Scene);
            scene.Dispose();
            Assert.Throws<ObjectDisposedException>(() => exposure.Measure(Occlusion.Eye));
            Assert.Throws<ObjectDisposedException>(() => new Exposure(scene, ExposureDesc.Default(), new double[] { 0, 0, 0 }));
            exposure.Dispose();
            exposure.Dispose();  // more than once
            Assert.IsTrue(exposure.IsDisposed);
        }

        private static double[] Filled(int length)
        {
            return Enumerable.Repeat(-7.0, length).ToArray();
        }
    }
}
