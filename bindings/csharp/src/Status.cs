// SPDX-License-Identifier: Apache-2.0
namespace Enteron
{
    /// <summary>
    /// The result of every C call that can fail (ent_status, ENT_OK and ENT_ERROR_* in
    /// enteron.h). The binding turns every status but <see cref="Ok"/> into an
    /// <see cref="EnteronException"/>.
    /// </summary>
    public enum Status
    {
        /// <summary>Success (ENT_OK).</summary>
        Ok = 0,
        /// <summary>A null handle or pointer, a non-finite number, or a value out of its range.</summary>
        InvalidArgument = 1,
        /// <summary>A struct_size the library does not know, or a saved state of a newer format.</summary>
        Version = 2,
        /// <summary>The JSON text is not well-formed JSON (the message gives the byte offset).</summary>
        Parse = 3,
        /// <summary>The scene description is well-formed but wrong: unknown key, wrong type, bad value.</summary>
        InvalidScene = 4,
        /// <summary>The step could not be made stable even with subdivided substeps; nothing changed.</summary>
        Unstable = 5,
        /// <summary>An allocation failed.</summary>
        OutOfMemory = 6,
        /// <summary>An id (tool, obstacle, effect) that does not exist in this scene.</summary>
        NotFound = 7,
        /// <summary>The caller's buffer is smaller than the data.</summary>
        BufferTooSmall = 8,
        /// <summary>A bug in the library: please report it with the message.</summary>
        Internal = 9,
        /// <summary>Another driving call runs on this scene on another thread; nothing was done.</summary>
        Busy = 10,
    }
}
