// SPDX-License-Identifier: Apache-2.0
using System;

namespace Enteron
{
    /// <summary>
    /// The calls that take no scene: the loaded library's version, the texts of statuses and
    /// effects, and this thread's last error. Safe from any thread.
    /// </summary>
    public static class Library
    {
        /// <summary>The major version this binding speaks (ENT_VERSION_MAJOR of its header).</summary>
        public const int SupportedMajor = 0;

        /// <summary>
        /// The version of the library actually loaded, packed (major &lt;&lt; 16) | (minor &lt;&lt; 8)
        /// | patch (ent_version). Throws DllNotFoundException when libenteron cannot be loaded.
        /// </summary>
        public static uint Version
        {
            get { return NativeMethods.ent_version(); }
        }

        /// <summary>The loaded library's version as "major.minor.patch".</summary>
        public static string VersionString
        {
            get
            {
                uint version = Version;
                return string.Format("{0}.{1}.{2}", version >> 16, (version >> 8) & 0xFF, version & 0xFF);
            }
        }

        /// <summary>
        /// The message of the last failing call on the calling thread (ent_last_error), or ""
        /// if none failed. An EnteronException's Message already carries it.
        /// </summary>
        public static string LastError
        {
            get { return Utf8.FromNative(NativeMethods.ent_last_error()); }
        }

        /// <summary>The library's short text for a status: "ok", "invalid argument", ...</summary>
        public static string StatusString(Status status)
        {
            return Utf8.FromNative(NativeMethods.ent_status_string(status));
        }

        /// <summary>The JSON-style name of an effect ("stretch", "gravity", ...), or null if the library does not know it.</summary>
        public static string EffectName(Effect effect)
        {
            return Utf8.FromNative(NativeMethods.ent_effect_name(effect));
        }

        private static volatile bool _compatible;

        /// <summary>
        /// Throws an <see cref="EnteronException"/> (<see cref="Status.Version"/>) when the
        /// loaded library's major version differs from <see cref="SupportedMajor"/>. Every
        /// scene factory calls it; the answer is kept after the first success.
        /// </summary>
        /// <exception cref="DllNotFoundException">libenteron cannot be loaded; the message says where it is looked for.</exception>
        public static void EnsureCompatible()
        {
            if (_compatible) return;
            uint version;
            try
            {
                version = Version;
            }
            catch (DllNotFoundException error)
            {
                throw new DllNotFoundException(
                    "Enteron.dll cannot load libenteron (DllImport \"enteron\": on Linux libenteron.so.0, named in " +
                    "Enteron.dll.config beside Enteron.dll): install it (Debian: libenteron0), add its directory to " +
                    "LD_LIBRARY_PATH, or, in Unity, put it among the package's plugins (" + error.Message + ")", error);
            }
            uint major = version >> 16;
            if (major != SupportedMajor)
                throw new EnteronException(Status.Version, "ent_version", string.Format(
                    "libenteron {0} is loaded; this binding (Enteron.dll) needs major version {1}",
                    VersionString, SupportedMajor));
            _compatible = true;
        }
    }
}
