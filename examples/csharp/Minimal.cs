// SPDX-License-Identifier: Apache-2.0
// The minimal example (examples/minimal.c) in C#: create a scene from JSON, step it for one
// simulated second, read the axis, print one line, the same line as the C program
// (ctest csharp.example_minimal compares them).
//
//   mono Minimal.exe    prints "minimal: t = 1.000 s, 100 axis points, first end at
//                       (-0.0833, 0.1158, -0.1538) m, lowest point z = -0.2492 m"
using System;
using System.Globalization;
using Enteron;

internal static class Minimal
{
    private const int AxisPoints = 100;

    private static int Main()
    {
        const string json =
            "{\"intestine\": {\"length\": 1.0, \"control_points\": 40," +
            "                 \"stretch_stiffness\": 100, \"bend_stiffness\": 2.5e-3}," +
            " \"gravity\": [0, 0, -9.81], \"damping\": {}, \"mesentery\": {}}";
        try
        {
            using (Scene scene = Scene.FromJson(json))  // also checks the library's major version
            {
                for (int i = 0; i < 1000; ++i) scene.Step(0.001);  // one simulated second in 1 ms steps
                var axis = new double[AxisPoints * 3];
                scene.Axis(axis);
                Stats stats = scene.GetStats();
                double lowest = axis[2];
                for (int i = 1; i < AxisPoints; ++i) lowest = Math.Min(lowest, axis[3 * i + 2]);
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                    "minimal: t = {0:F3} s, {1} axis points, first end at ({2:F4}, {3:F4}, {4:F4}) m, lowest point z = {5:F4} m",
                    stats.time_s, AxisPoints, axis[0], axis[1], axis[2], lowest));
            }
            return 0;
        }
        catch (EnteronException error)
        {
            Console.Error.WriteLine("minimal: " + error.Function + ": " + error.Message);
            return 1;
        }
    }
}
