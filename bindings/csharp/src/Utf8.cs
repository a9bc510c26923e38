// SPDX-License-Identifier: Apache-2.0
using System;
using System.Text;

namespace Enteron
{
    /// <summary>The UTF-8 strings that cross the C API, in both directions.</summary>
    internal static unsafe class Utf8
    {
        /// <summary>A NUL-terminated string owned by the library, decoded; null for NULL.</summary>
        internal static string FromNative(IntPtr text)
        {
            if (text == IntPtr.Zero) return null;
            byte* bytes = (byte*)text;
            int length = 0;
            while (bytes[length] != 0) ++length;
            return length == 0 ? string.Empty : Encoding.UTF8.GetString(bytes, length);
        }

        /// <summary>The text as UTF-8 bytes with a NUL at the end (for a C path).</summary>
        internal static byte[] NulTerminated(string text)
        {
            int length = Encoding.UTF8.GetByteCount(text);
            byte[] bytes = new byte[length + 1];
            Encoding.UTF8.GetBytes(text, 0, text.Length, bytes, 0);
            return bytes;
        }
    }
}
