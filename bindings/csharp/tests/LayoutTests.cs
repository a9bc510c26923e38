// SPDX-License-Identifier: Apache-2.0
// Every struct marked [CStruct] has the C compiler's layout: its size, and each C field at
// the same offset with the same size and name (the C layouts come from
// bindings/python/tests/struct_layout.c, built by ctest). A field appended to a C struct
// changes its size and fails here until the binding has it too.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace Enteron.Tests
{
    [TestFixture]
    public class LayoutTests
    {
        private struct CField
        {
            internal int Offset;
            internal int Size;
        }

        private sealed class CStruct
        {
            internal int Size;
            internal readonly Dictionary<string, CField> Fields = new Dictionary<string, CField>();
        }

        /// <summary>{"ent_stats": {"size": 80, "fields": {"struct_size": [0, 4], ...}}, ...}</summary>
        private static Dictionary<string, CStruct> CLayouts()
        {
            var start = new ProcessStartInfo(TestPaths.FromEnvironment("ENTERON_STRUCT_LAYOUT"))
            {
                UseShellExecute = false,
                RedirectStandardOutput = true,
            };
            string json;
            using (Process program = Process.Start(start))
            {
                json = program.StandardOutput.ReadToEnd();
                program.WaitForExit();
                Assert.AreEqual(0, program.ExitCode, "enteron_struct_layout failed");
            }
            var layouts = new Dictionary<string, CStruct>();
            foreach (Match type in Regex.Matches(json, "\"(\\w+)\": \\{\"size\": (\\d+), \"fields\": \\{([^}]*)\\}\\}"))
            {
                var layout = new CStruct { Size = int.Parse(type.Groups[2].Value) };
                foreach (Match field in Regex.Matches(type.Groups[3].Value, "\"(\\w+)\": \\[(\\d+), (\\d+)\\]"))
                    layout.Fields[field.Groups[1].Value] = new CField
                    {
                        Offset = int.Parse(field.Groups[2].Value),
                        Size = int.Parse(field.Groups[3].Value),
                    };
                layouts[type.Groups[1].Value] = layout;
            }
            Assert.Greater(layouts.Count, 10, "no layouts read from enteron_struct_layout's output");
            return layouts;
        }

        private static IEnumerable<Type> Mirrors()
        {
            return typeof(Scene).Assembly.GetTypes().Where(t => t.GetCustomAttributes(typeof(CStructAttribute), false).Length > 0);
        }

        private static string CName(Type type)
        {
            return ((CStructAttribute)type.GetCustomAttributes(typeof(CStructAttribute), false)[0]).Name;
        }

        [Test]
        public void EveryCStructHasItsMirrorAndEveryMirrorTheCLayout()
        {
            Dictionary<string, CStruct> layouts = CLayouts();
            var problems = new List<string>();
            var mirrored = new HashSet<string>();
            foreach (Type type in Mirrors())
            {
                string name = CName(type);
                mirrored.Add(name);
                CStruct layout;
                if (!layouts.TryGetValue(name, out layout))
                {
                    problems.Add(type.Name + " mirrors " + name + ", which struct_layout.c does not list");
                    continue;
                }
                int size = Marshal.SizeOf(type);
                if (size != layout.Size) problems.Add(string.Format("{0} ({1}): {2} bytes, C has {3}", type.Name, name, size, layout.Size));
                FieldInfo[] fields = type.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic);
                foreach (var field in layout.Fields)
                {
                    FieldInfo mine = fields.FirstOrDefault(f => f.Name == field.Key);
                    if (mine == null)
                    {
                        problems.Add(type.Name + " lacks " + name + "." + field.Key);
                        continue;
                    }
                    int offset = Marshal.OffsetOf(type, field.Key).ToInt32();
                    int fieldSize = Marshal.SizeOf(mine.FieldType.IsEnum ? Enum.GetUnderlyingType(mine.FieldType) : mine.FieldType);
                    if (offset != field.Value.Offset || fieldSize != field.Value.Size)
                        problems.Add(string.Format("{0}.{1}: offset {2}, {3} bytes; C: offset {4}, {5} bytes", type.Name, field.Key,
                                                   offset, fieldSize, field.Value.Offset, field.Value.Size));
                }
                foreach (FieldInfo mine in fields.Where(f => !layout.Fields.ContainsKey(f.Name)))
                    problems.Add(type.Name + "." + mine.Name + ": no such field in " + name);
            }
            foreach (string name in layouts.Keys.Where(n => !mirrored.Contains(n)))
                problems.Add(name + ": no [CStruct(\"" + name + "\")] struct in the binding");
            Assert.IsEmpty(problems, string.Join("\n", problems.ToArray()));
        }

        [Test]
        public void TheSmallArraysAreTheirCArrays()
        {
            Assert.AreEqual(3 * sizeof(double), Marshal.SizeOf(typeof(Vec3)));
            Assert.AreEqual(4 * sizeof(double), Marshal.SizeOf(typeof(Quat)));
            Assert.AreEqual(9 * sizeof(double), Marshal.SizeOf(typeof(Matrix3)));
            Assert.AreEqual(8, Marshal.OffsetOf(typeof(Quat), "X").ToInt32(), "w first");
            Assert.AreEqual(8, Marshal.OffsetOf(typeof(Matrix3), "M01").ToInt32(), "row-major");
            var m = new Matrix3 { M01 = 2, M10 = 3 };
            Assert.AreEqual(2.0, m[0, 1]);
            Assert.AreEqual(3.0, m[1, 0]);
            Assert.Throws<ArgumentOutOfRangeException>(() => { double unused = m[3, 0]; });
        }
    }
}
