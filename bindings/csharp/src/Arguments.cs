// SPDX-License-Identifier: Apache-2.0
// Checks of the caller's arrays before their pointers reach C: the library trusts a
// capacity it is given, so a capacity larger than the array would let it write past the
// array's end. Each check throws on the error path only (the success path allocates nothing).
using System;

namespace Enteron
{
    internal static class Arguments
    {
        /// <summary>Throws unless <paramref name="array"/> is non-null.</summary>
        internal static void NotNull(object array, string name)
        {
            if (array == null) throw new ArgumentNullException(name);
        }

        /// <summary>Throws unless <paramref name="length"/> is a multiple of <paramref name="stride"/> (x y z triples, index triples).</summary>
        internal static void Multiple(int length, int stride, string name, string what)
        {
            if (length % stride != 0)
                throw new ArgumentException(string.Format("{0} must hold {1} numbers per {2}, got {3} numbers",
                                                          name, stride, what, length), name);
        }

        /// <summary>Throws unless 0 &lt;= count and count * stride &lt;= length.</summary>
        internal static void Fits(int count, int stride, int length, string name)
        {
            if (count < 0) throw new ArgumentOutOfRangeException("count", count, "must be >= 0");
            if ((long)count * stride > length)
                throw new ArgumentException(string.Format("{0} holds {1} numbers, {2} are needed ({3} x {4})", name,
                                                          length, (long)count * stride, count, stride), name);
        }

        /// <summary>Throws unless index >= 0 (C takes it as an unsigned number).</summary>
        internal static uint Index(int index, string name)
        {
            if (index < 0) throw new ArgumentOutOfRangeException(name, index, "must be >= 0");
            return (uint)index;
        }
    }
}
