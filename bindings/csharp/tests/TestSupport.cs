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
