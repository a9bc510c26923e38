// SPDX-License-Identifier: Apache-2.0
// The binding covers the whole C API, and says so (as MuJoCo's doc test): every function
// libenteron exports has a [DllImport] in NativeMethods.cs, a caller among the binding's
// classes and a row in bindings/csharp/README.md naming its C# counterpart (or why there
// is none); every ENT_* constant family of enteron.h is an enum with the same values.
// A function or constant another branch adds to the C API fails here until it is bound.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public class DocTests
    {
        private static readonly Assembly Binding = typeof(Scene).Assembly;

        private static string[] Exports()
        {
            return File.ReadAllLines(TestPaths.FromEnvironment("ENTERON_EXPORTS_FILE"))
                       .Select(line => line.Trim()).Where(line => line.Length > 0).ToArray();
        }

        private static MethodInfo[] Imports()
        {
            Type native = Binding.GetType("Enteron.NativeMethods", true);
            return native.GetMethods(BindingFlags.Static | BindingFlags.NonPublic | BindingFlags.Public)
                         .Where(method => method.GetCustomAttributes(typeof(DllImportAttribute), false).Length > 0)
                         .ToArray();
        }

        private static string ImportName(MethodInfo method)
        {
            var import = (DllImportAttribute)method.GetCustomAttributes(typeof(DllImportAttribute), false)[0];
            return string.IsNullOrEmpty(import.EntryPoint) ? method.Name : import.EntryPoint;
        }

        [Test]
        public void EveryExportedFunctionIsImportedAndEveryImportIsExported()
        {
            string[] exports = Exports();
            Assert.Greater(exports.Length, 40, "the export list looks empty");
            var imported = new HashSet<string>(Imports().Select(ImportName));
            CollectionAssert.IsEmpty(exports.Where(name => !imported.Contains(name)).ToArray(),
                                     "exported by libenteron, not declared in bindings/csharp/src/NativeMethods.cs");
            CollectionAssert.IsEmpty(imported.Where(name => !exports.Contains(name)).ToArray(),
                                     "declared in NativeMethods.cs, not exported by libenteron");
        }

        [Test]
        public void EveryImportResolvesInTheLoadedLibrary()
        {
            foreach (MethodInfo method in Imports()) Marshal.Prelink(method);  // EntryPointNotFoundException if not
        }

        [Test]
        public void EveryImportHasACallerInTheBinding()
        {
            string sources = TestPaths.Source("bindings/csharp/src");
            string callers = string.Join("\n", Directory.GetFiles(sources, "*.cs")
                                                        .Where(path => Path.GetFileName(path) != "NativeMethods.cs")
                                                        .Select(File.ReadAllText).ToArray());
            CollectionAssert.IsEmpty(Imports().Select(ImportName)
                                              .Where(name => !callers.Contains("NativeMethods." + name + "(")).ToArray(),
                                     "declared in NativeMethods.cs but called by no class of the binding");
        }

        [Test]
        public void TheReadmeNamesTheCounterpartOfEveryFunction()
        {
            string readme = TestPaths.Source("bindings/csharp/README.md");
            var rows = new Dictionary<string, string>();
            var row = new Regex(@"^\|\s*`(ent_[a-z0-9_]+)`\s*\|(.*)\|\s*$");
            foreach (string line in File.ReadAllLines(readme))
            {
                Match match = row.Match(line);
                if (!match.Success) continue;
                Assert.IsFalse(rows.ContainsKey(match.Groups[1].Value), match.Groups[1].Value + ": two rows in README.md");
                rows[match.Groups[1].Value] = match.Groups[2].Value;
            }
            var problems = new List<string>();
            foreach (string function in Exports())
            {
                string counterpart;
                if (!rows.TryGetValue(function, out counterpart))
                {
                    problems.Add(function + ": no row in bindings/csharp/README.md's table");
                    continue;
                }
                MatchCollection members = Regex.Matches(counterpart, @"`([A-Z][A-Za-z0-9]*)(?:\.([A-Z][A-Za-z0-9]*))?[^`]*`");
                if (members.Count == 0 && !counterpart.Contains("not bound:"))
                    problems.Add(function + ": its row names no C# member (`Type.Member`) and no reason (\"not bound: ...\")");
                foreach (Match member in members)
                {
                    Type type = Binding.GetType("Enteron." + member.Groups[1].Value);
                    if (type == null || !type.IsPublic)
                        problems.Add(function + ": README names `" + member.Groups[1].Value + "`, which is no public type");
                    else if (member.Groups[2].Success && type.GetMember(member.Groups[2].Value).Length == 0)
                        problems.Add(function + ": README names `" + member.Value.Trim('`') + "`, which " + type.Name + " does not have");
                }
            }
            foreach (string function in rows.Keys.Where(name => !Exports().Contains(name)))
                problems.Add(function + ": a row in README.md, but libenteron does not export it");
            Assert.IsEmpty(problems, string.Join("\n", problems.ToArray()));
        }

        // enum type -> the prefix of its constants in enteron.h, and constants of that prefix that are not values
        private static readonly object[][] Families =
        {
            new object[] { typeof(Status), "ENT_ERROR_", new string[0] },
            new object[] { typeof(Effect), "ENT_EFFECT_", new[] { "ENT_EFFECT_COUNT", "ENT_EFFECT_BIT" } },
            new object[] { typeof(Shape), "ENT_SHAPE_", new string[0] },
            new object[] { typeof(Integrator), "ENT_INTEGRATOR_", new string[0] },
            new object[] { typeof(PinnedEnds), "ENT_PIN_", new string[0] },
            new object[] { typeof(ObstacleKind), "ENT_OBSTACLE_", new string[0] },
            new object[] { typeof(ToolMode), "ENT_TOOL_MODE_", new string[0] },
            new object[] { typeof(ContactKind), "ENT_CONTACT_", new string[0] },
            new object[] { typeof(SkinMethod), "ENT_SKIN_", new string[0] },
            new object[] { typeof(LogLevel), "ENT_LOG_", new string[0] },
        };

        /// <summary>ENT_EFFECT_SELF_COLLISION -> SelfCollision; ENT_INTEGRATOR_RK4 -> Rk4.</summary>
        private static string EnumName(string constant, string prefix)
        {
            return string.Concat(constant.Substring(prefix.Length).Split('_')
                                         .Select(word => word.Substring(0, 1) + word.Substring(1).ToLowerInvariant()).ToArray());
        }

        [Test]
        public void EveryConstantFamilyOfTheHeaderIsAnEnumWithItsValues()
        {
            string header = File.ReadAllText(TestPaths.Source("include/enteron/enteron.h"));
            var defines = new Dictionary<string, int>();
            foreach (Match define in Regex.Matches(header, @"^#define (ENT_[A-Z0-9_]+) +\(?(-?\d+)\)?", RegexOptions.Multiline))
                defines[define.Groups[1].Value] = int.Parse(define.Groups[2].Value);
            Assert.AreEqual(0, defines["ENT_OK"]);
            Assert.AreEqual(Scene.NoObstacle, defines["ENT_NO_OBSTACLE"]);
            Assert.AreEqual((int)Effects.Tools, 1 << defines["ENT_EFFECT_TOOLS"]);
            Assert.AreEqual(defines["ENT_EFFECT_COUNT"], Enum.GetValues(typeof(Effect)).Length);
            var problems = new List<string>();
            foreach (object[] family in Families)
            {
                var type = (Type)family[0];
                var prefix = (string)family[1];
                var skip = (string[])family[2];
                var expected = defines.Where(d => d.Key.StartsWith(prefix, StringComparison.Ordinal) && !skip.Contains(d.Key))
                                      .ToDictionary(d => EnumName(d.Key, prefix), d => d.Value);
                if (type == typeof(Status)) expected["Ok"] = 0;
                foreach (var constant in expected)
                {
                    if (!Enum.IsDefined(type, constant.Key))
                        problems.Add(prefix + "*: " + type.Name + " has no " + constant.Key + " (= " + constant.Value + ")");
                    else if ((int)Enum.Parse(type, constant.Key) != constant.Value)
                        problems.Add(type.Name + "." + constant.Key + " is " + (int)Enum.Parse(type, constant.Key) +
                                     ", the header says " + constant.Value);
                }
                foreach (string name in Enum.GetNames(type).Where(name => !expected.ContainsKey(name)))
                    problems.Add(type.Name + "." + name + ": no " + prefix + "* constant in enteron.h");
            }
            Assert.IsEmpty(problems, string.Join("\n", problems.ToArray()));
        }
    }
}
