// SPDX-License-Identifier: Apache-2.0
// What the fixtures share: the scenes they run, the paths ctest gives them, small checks.
using System;
using System.Globalization;
using System.IO;
using NUnit.Framework;

namespace Enteron.Tests
{
    internal static class TestScenes
    {
        internal const double Radius = 0.0125;

        /// <summary>The minimal example's scene (examples/minimal.c): 1 m, 40 control points, hanging from its mesentery.</summary>
        internal const string Minimal =
            "{\"intestine\": {\"length\": 1.0, \"control_points\": 40," +
            " \"stretch_stiffness\": 100, \"bend_stiffness\": 2.5e-3}," +
            " \"gravity\": [0, 0, -9.81], \"damping\": {}, \"mesentery\": {}}";

        /// <summary>
        /// A 0.4 m bowel along x lying on the floor z = 0 (examples/python/tools.py), with its
        /// self-contact, and a vertical tool beside it at y = 0.05.
        /// </summary>
        internal const string OnTheFloor =
            "{\"intestine\": {\"length\": 0.4, \"control_points\": 17, \"stretch_stiffness\": 100," +
            " \"bend_stiffness\": 2.5e-3, \"shape\": {\"kind\": \"line\", \"center\": [-0.2, 0, 0.0125]}}," +
            " \"gravity\": [0, 0, -9.81], \"damping\": {}, \"self_collision\": {}," +
            " \"environment\": [{\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 0, 1]}]," +
            " \"tools\": [{\"radius\": 0.005, \"max_force\": 5, \"position\": [0, 0.05, 0.0125]}]}";

        internal const double MaxForce = 5.0;

        /// <summary>Pushes the bowel of <see cref="OnTheFloor"/> along -y with its tool: 1e-4 m per 1 ms step.</summary>
        internal static void Push(Scene scene, Tool tool, int fromStep, int steps)
        {
            for (int i = fromStep + 1; i <= fromStep + steps; ++i)
            {
                tool.SetPose(new Vec3(0, 0.05 - 1e-4 * i, Radius), Quat.Identity);
                scene.Step(0.001);
            }
        }
    }

    /// <summary>
    /// The analytic case of tests/capi/test_exposure.cpp: a straight tube of radius R along x
    /// with its axis at height h above the plane z = 0, seen from an eye at height H above the
    /// axis. A point of the plane is hidden when its sight line passes within R of the axis:
    /// |y| (H - h) / sqrt(y^2 + H^2) &lt; R, the band |y| &lt; w = R H / sqrt((H - h)^2 - R^2).
    /// </summary>
    internal static class Occlusion
    {
        internal const double EyeHeight = 0.30;   // H, m
        internal const double AxisHeight = 0.05;  // h, m
        internal const double TubeLength = 2.0;   // m, centred on x = 0

        internal static readonly Vec3 Eye = new Vec3(0, 0, EyeHeight);

        /// <summary>w: the half width of the band the tube hides.</summary>
        internal static double BandHalfWidth()
        {
            const double R = TestScenes.Radius, H = EyeHeight, h = AxisHeight;
            return R * H / Math.Sqrt((H - h) * (H - h) - R * R);
        }

        /// <summary>Whether the tube hides the point (x, y, 0) of the plane from the eye.</summary>
        internal static bool Hidden(double y)
        {
            return Math.Abs(y) * (EyeHeight - AxisHeight) / Math.Sqrt(y * y + EyeHeight * EyeHeight) < TestScenes.Radius;
        }

        /// <summary>The straight tube, 81 control points, at rest with only stretch and bend (or the effects given).</summary>
        internal static Scene StraightTube(Effects effects = Effects.Stretch | Effects.Bend)
        {
            SceneDesc desc = SceneDesc.Default();
            desc.effects = effects;
            desc.shape = Shape.Line;
            desc.length_m = TubeLength;
            desc.control_points = 81;
            desc.radius_m = TestScenes.Radius;
            desc.shape_center_m = new Vec3(-TubeLength / 2, 0, AxisHeight);  // a line's start
            desc.shape_direction = new Vec3(1, 0, 0);
            return Scene.FromDescription(desc);
        }

        /// <summary>A regular 64-gon of radius rho around (cx, cy) in the plane z = 0, a fan of 64 triangles.</summary>
        internal static void Disk(double cx, double cy, double rho, out double[] pointsXyz, out uint[] triangles)
        {
            const int sides = 64;
            pointsXyz = new double[3 * (sides + 1)];
            triangles = new uint[3 * sides];
            pointsXyz[0] = cx;
            pointsXyz[1] = cy;
            for (int k = 0; k < sides; ++k)
            {
                double a = 2.0 * Math.PI * (k + 0.5) / sides;  // symmetric about the x and y axes
                pointsXyz[3 * (k + 1)] = cx + rho * Math.Cos(a);
                pointsXyz[3 * (k + 1) + 1] = cy + rho * Math.Sin(a);
                triangles[3 * k] = 0;
                triangles[3 * k + 1] = (uint)(1 + k);
                triangles[3 * k + 2] = (uint)(1 + (k + 1) % sides);
            }
        }
    }

    internal static class TestPaths
    {
        /// <summary>An environment variable that ctest sets (bindings/csharp/tests/csharp_tests.cmake).</summary>
        internal static string FromEnvironment(string name)
        {
            string value = Environment.GetEnvironmentVariable(name);
            if (string.IsNullOrEmpty(value)) Assert.Fail(name + " is not set: run the tests through ctest");
            return value;
        }

        internal static string Source(string relative)
        {
            return Path.Combine(FromEnvironment("ENTERON_SOURCE_DIR"), relative);
        }
    }

    internal static class Bits
    {
        /// <summary>Asserts that two arrays hold the same doubles, bit for bit.</summary>
        internal static void AssertSame(double[] expected, double[] actual, string what)
        {
            Assert.AreEqual(expected.Length, actual.Length, what + ": lengths");
            for (int i = 0; i < expected.Length; ++i)
                if (BitConverter.DoubleToInt64Bits(expected[i]) != BitConverter.DoubleToInt64Bits(actual[i]))
                    Assert.Fail(string.Format(CultureInfo.InvariantCulture, "{0}: element {1} differs: {2:R} != {3:R}",
                                              what, i, expected[i], actual[i]));
        }
    }
}
