// SPDX-License-Identifier: Apache-2.0
// The C# side of bench/csharp/compare_call_overhead.sh: the calls of call_overhead.c
// through Enteron.dll (Library.Version, Scene.Step, Tool.ReadFeedback), timed the same way.
//
//   mono CallOverhead.exe SCENE.json [--rounds N] [--calls N]
//   prints "C#: version_ns 20.3 step_ns 850.1 read_feedback_ns 130.4"
using System;
using System.Diagnostics;
using System.Globalization;
using Enteron;

internal static class CallOverhead
{
    private const double Dt = 0.001;

    private static int Main(string[] args)
    {
        int rounds = 21, calls = 20000;
        for (int i = 1; i + 1 < args.Length; i += 2)
        {
            if (args[i] == "--rounds") rounds = int.Parse(args[i + 1]);
            else if (args[i] == "--calls") calls = int.Parse(args[i + 1]);
        }
        var perCall = new double[3, rounds];
        uint sink = 0;
        using (Scene scene = Scene.FromFile(args[0]))
        {
            Tool tool = scene.GetTool(0);
            var feedback = new ToolFeedback();
            double nsPerTick = 1e9 / Stopwatch.Frequency;
            for (int round = -1; round < rounds; ++round)  // round -1 warms up (and compiles)
            {
                for (int which = 0; which < 3; ++which)
                {
                    long start = Stopwatch.GetTimestamp();
                    for (int i = 0; i < calls; ++i)
                    {
                        if (which == 0) sink += Library.Version;
                        else if (which == 1) scene.Step(Dt);
                        else tool.ReadFeedback(ref feedback);
                    }
                    if (round >= 0) perCall[which, round] = (Stopwatch.GetTimestamp() - start) * nsPerTick / calls;
                }
            }
        }
        Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "C#: version_ns {0:F1} step_ns {1:F1} read_feedback_ns {2:F1}",
                                        Median(perCall, 0, rounds), Median(perCall, 1, rounds), Median(perCall, 2, rounds)));
        return sink == 0xFFFFFFFFu ? 1 : 0;
    }

    private static double Median(double[,] values, int which, int count)
    {
        var row = new double[count];
        for (int i = 0; i < count; ++i) row[i] = values[which, i];
        Array.Sort(row);
        return count % 2 == 1 ? row[count / 2] : 0.5 * (row[count / 2 - 1] + row[count / 2]);
    }
}
