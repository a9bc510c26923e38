// SPDX-License-Identifier: Apache-2.0
// The assembled Unity package (target enteron_unity_package): what the Package Manager
// reads is there, every asset it imports has a .meta with its own GUID, the stand-in is
// not shipped, and the tarball holds the same tree under package/.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using Enteron.Tests;
using NUnit.Framework;

namespace Enteron.Unity.Tests
{
    [TestFixture]
    public class UnityPackageTests
    {
        private static string Package
        {
            get { return TestPaths.FromEnvironment("ENTERON_UNITY_PACKAGE"); }
        }

        [Test]
        public void PackageJsonNamesThisVersionAndItsSample()
        {
            string json = File.ReadAllText(Path.Combine(Package, "package.json"));
            StringAssert.Contains("\"name\": \"com.enteron.unity\"", json);
            StringAssert.Contains("\"version\": \"" + TestPaths.FromEnvironment("ENTERON_VERSION") + "\"", json,
                                  "bindings/unity/package.json's version is the project's");
            foreach (Match path in Regex.Matches(json, "\"path\": \"([^\"]+)\""))
                Assert.IsTrue(Directory.Exists(Path.Combine(Package, path.Groups[1].Value)), path.Groups[1].Value);
            Assert.IsTrue(File.Exists(Path.Combine(Package, "Samples~/Abdomen/Scenes/abdomen.json")));
            Assert.IsTrue(File.Exists(Path.Combine(Package, "Samples~/Abdomen/Scenes/organs/liver.obj")));
            Assert.IsTrue(File.Exists(Path.Combine(Package, "Documentation~/enteron.md")));
        }

        [Test]
        public void ThePluginsAreInPlaceAndTheStandInIsNot()
        {
            Assert.IsTrue(File.Exists(Path.Combine(Package, "Runtime/Plugins/Enteron.dll")));
            Assert.IsTrue(File.Exists(Path.Combine(Package, "Runtime/Plugins/x86_64/libenteron.so")));
            Assert.IsTrue(File.Exists(Path.Combine(Package, "Runtime/Enteron.Unity.asmdef")));
            foreach (string file in Directory.GetFiles(Package, "*", SearchOption.AllDirectories))
                StringAssert.DoesNotContain("StandIn", Path.GetFileName(file), "the stand-in is never shipped");
        }

        [Test]
        public void EveryImportedAssetHasAMetaWithItsOwnGuid()
        {
            var guids = new Dictionary<string, string>();
            var problems = new List<string>();
            foreach (string path in Directory.GetFileSystemEntries(Package, "*", SearchOption.AllDirectories))
            {
                string relative = path.Substring(Package.Length + 1);
                if (relative.EndsWith(".meta") || Regex.IsMatch(relative, "~(/|$)")) continue;
                string meta = path + ".meta";
                if (!File.Exists(meta))
                {
                    problems.Add(relative + ": no .meta");
                    continue;
                }
                Match guid = Regex.Match(File.ReadAllText(meta), "^guid: ([0-9a-f]{32})$", RegexOptions.Multiline);
                if (!guid.Success) problems.Add(relative + ".meta: no guid");
                else if (guids.ContainsKey(guid.Groups[1].Value)) problems.Add(relative + ": the guid of " + guids[guid.Groups[1].Value]);
                else guids[guid.Groups[1].Value] = relative;
            }
            Assert.IsEmpty(problems, string.Join("\n", problems.ToArray()));
            Assert.Greater(guids.Count, 10);
        }

        [Test]
        public void TheTarballHoldsThePackageUnderPackage()
        {
            var start = new ProcessStartInfo("tar", "-tzf \"" + TestPaths.FromEnvironment("ENTERON_UNITY_TARBALL") + "\"")
            {
                UseShellExecute = false,
                RedirectStandardOutput = true,
            };
            string[] entries;
            using (Process tar = Process.Start(start))
            {
                entries = tar.StandardOutput.ReadToEnd().Split('\n').Where(line => line.Length > 0).ToArray();
                tar.WaitForExit();
                Assert.AreEqual(0, tar.ExitCode);
            }
            CollectionAssert.Contains(entries, "package/package.json");
            CollectionAssert.Contains(entries, "package/Runtime/EnteronScene.cs.meta");
            Assert.IsTrue(entries.All(entry => entry.StartsWith("package/", StringComparison.Ordinal)));
        }
    }
}
