// SPDX-License-Identifier: Apache-2.0
// The package's sample, run on the UnityEngine stand-in: it opens the abdomen scene, draws
// the bowel and the organs, lifts the liver and moves the grasper as abdomen_motion.h does.
using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using System.Threading;
using Enteron.Samples;
using Enteron.Tests;
using NUnit.Framework;
using UnityEngine;
using UnityEngineStandIn;

namespace Enteron.Unity.Tests
{
    [TestFixture]
    public class AbdomenSampleTests
    {
        [TearDown]
        public void LeavePlayMode()
        {
            Player.DestroyAll();
            Player.Logged.Clear();
        }

        [Test]
        public void TheSampleOpensTheAbdomenAndPlaysItsMotion()
        {
            var holder = new GameObject("sample");
            holder.SetActive(false);
            AbdomenSample sample = holder.AddComponent<AbdomenSample>();
            sample.sceneFile = TestPaths.Source("examples/scenes/abdomen.json");
            holder.SetActive(true);
            Assert.IsNotNull(sample.Scene, string.Join("\n", Player.Logged.ToArray()));
            Scene scene = sample.Scene.Scene;
            Assert.AreEqual(3, scene.ObstacleCount, "the wall, the liver, the stomach");
            Vec3 liverStart;
            Quat orientation;
            scene.GetObstaclePose(AbdomenSample.Liver, out liverStart, out orientation);

            var clock = Stopwatch.StartNew();
            while (sample.Scene.Steps < 1600 && clock.Elapsed.TotalSeconds < 60)  // the liver is up from 1.5 s
            {
                Player.Frame(1f / 60f);
                Thread.Sleep(15);
            }
            Player.Frame(1f / 60f);
            Console.WriteLine("abdomen sample: {0} steps in {1:F1} s of wall time", sample.Scene.Steps, clock.Elapsed.TotalSeconds);
            Assert.GreaterOrEqual(sample.Scene.Steps, 1600);
            Assert.AreEqual(0, sample.Scene.FailedSteps);
            Vec3 liver;
            scene.GetObstaclePose(AbdomenSample.Liver, out liver, out orientation);
            Assert.AreEqual(liverStart.Z + 0.04, liver.Z, 1e-9, "the retractor lifted the liver 4 cm");

            GameObject root = sample.Scene.gameObject;
            Transform liverObject = root.transform.Find("Liver");
            Assert.IsNotNull(liverObject, "an object per organ");
            Assert.AreEqual((float)liver.Z, liverObject.localPosition.y, 1e-6f, "moved to the liver's pose (Unity's up)");
            Assert.Greater(liverObject.GetComponent<MeshFilter>().sharedMesh.vertexCount, 100);
            Mesh bowel = root.transform.Find("Bowel").GetComponent<MeshFilter>().sharedMesh;
            Assert.Greater(bowel.vertexCount, 1000, "the 6 m bowel is drawn");
            Assert.IsTrue(sample.Grasper.Tool != null && sample.Grasper.Tool.Id == 0, "the file's grasper");
            Vec3 commanded = sample.Grasper.ReadFeedback().commanded_position_m;
            Assert.AreEqual(-0.06, commanded.X, 1e-6, "the grasper went across (abdomen_motion.h)");
        }

        [Test]
        public void TheSamplesMotionIsAbdomenMotionH()
        {
            string header = File.ReadAllText(TestPaths.Source("examples/abdomen_motion.h"));
            CollectionAssert.AreEqual(Keys(header, "abdomen_liver_keys"), AbdomenSample.LiverKeys);
            CollectionAssert.AreEqual(Keys(header, "abdomen_tool_keys"), AbdomenSample.ToolKeys);
        }

        private static double[] Keys(string header, string name)
        {
            Match array = Regex.Match(header, name + @"\[\] = \{([^}]*)\}");
            Assert.IsTrue(array.Success, name + " not found in abdomen_motion.h");
            return array.Groups[1].Value.Split(',').Select(number => double.Parse(number.Trim(),
                System.Globalization.CultureInfo.InvariantCulture)).ToArray();
        }
    }
}
