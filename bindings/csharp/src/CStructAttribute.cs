// SPDX-License-Identifier: Apache-2.0
using System;

namespace Enteron
{
    /// <summary>
    /// Marks a struct that mirrors a C struct of enteron.h field for field (same names, same
    /// layout). The test LayoutTests compares every such struct with the C compiler's
    /// layout, so a field that another release appends to the header is caught here.
    /// </summary>
    [AttributeUsage(AttributeTargets.Struct, Inherited = false)]
    public sealed class CStructAttribute : Attribute
    {
        /// <summary>The C name: "ent_tool_feedback".</summary>
        public string Name { get; private set; }

        /// <summary>Marks the struct as the mirror of the C struct <paramref name="name"/>.</summary>
        public CStructAttribute(string name)
        {
            Name = name;
        }
    }

    /// <summary>The size of a mirrored struct, as its struct_size field wants it.</summary>
    internal static class StructSize<T> where T : struct
    {
        internal static readonly uint Value = (uint)System.Runtime.InteropServices.Marshal.SizeOf(typeof(T));
    }
}
