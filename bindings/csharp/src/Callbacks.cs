// SPDX-License-Identifier: Apache-2.0
// A scene's optional hooks (ent_callbacks): a managed log handler, and native allocator
// functions for those who bring their own. The log handler reaches C as one static
// function (IL2CPP needs a static reverse P/Invoke) whose user_data is a GCHandle of the
// handler; the handle lives until the scene and all its skins are released, because the
// library may call the hooks until then (enteron.h, ent_callbacks).
using System;
using System.Runtime.InteropServices;
using System.Threading;

namespace Enteron
{
    /// <summary>Receives a scene's log lines, on the thread of the call that logs (the creating thread, the stepping thread).</summary>
    /// <param name="level">how serious</param>
    /// <param name="message">the line, naming what it is about</param>
    public delegate void LogHandler(LogLevel level, string message);

    /// <summary>
    /// Optional hooks of a scene (ent_callbacks). With none the library is silent and uses
    /// malloc/free.
    /// </summary>
    public sealed class Callbacks
    {
        /// <summary>
        /// Receives the scene's log lines (warnings about implausible values, ...). It runs on
        /// the thread of the call that logs and must not call back into the scene; an
        /// exception it throws is caught and dropped (it cannot cross the C library).
        /// </summary>
        public LogHandler Log;

        /// <summary>
        /// A native allocator function, void* (*)(void* user_data, size_t size, size_t
        /// alignment), or IntPtr.Zero. Both or neither of NativeAllocate and NativeRelease.
        /// It must stay valid until the scene and all its skins are disposed.
        /// </summary>
        public IntPtr NativeAllocate;

        /// <summary>The matching void (*)(void* user_data, void* memory, size_t size, size_t alignment).</summary>
        public IntPtr NativeRelease;

        /// <summary>user_data passed to the native allocator functions. Not with <see cref="Log"/>, which needs user_data for itself.</summary>
        public IntPtr NativeUserData;
    }

    /// <summary>ent_callbacks as C lays it out.</summary>
    [CStruct("ent_callbacks")]
    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeCallbacks
    {
        internal uint struct_size;
        internal IntPtr log;
        internal IntPtr allocate;
        internal IntPtr release;
        internal IntPtr user_data;
    }

    /// <summary>
    /// The hooks handed to one scene, alive until the scene and every skin made from it are
    /// released (each holds a reference: <see cref="AddReference"/>, <see cref="Release"/>).
    /// </summary>
    internal sealed class CallbackState
    {
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        private delegate void NativeLogFunction(IntPtr userData, int level, IntPtr message);

        // One delegate for every scene, never collected: C holds its function pointer.
        private static readonly NativeLogFunction LogTrampoline = ForwardLog;
        private static readonly IntPtr LogTrampolinePointer = Marshal.GetFunctionPointerForDelegate(LogTrampoline);

        private readonly LogHandler _log;
        private GCHandle _self;
        private int _references;

        /// <summary>The C struct to pass at creation.</summary>
        internal NativeCallbacks Native;

        private CallbackState(Callbacks callbacks)
        {
            if (callbacks.Log != null && callbacks.NativeUserData != IntPtr.Zero)
                throw new ArgumentException("Callbacks.Log and Callbacks.NativeUserData cannot be used together: " +
                                            "the log handler needs user_data for itself", "callbacks");
            _log = callbacks.Log;
            Native = new NativeCallbacks();
            EnteronException.Check(NativeMethods.ent_callbacks_init(ref Native, StructSize<NativeCallbacks>.Value),
                                   "ent_callbacks_init");
            Native.allocate = callbacks.NativeAllocate;
            Native.release = callbacks.NativeRelease;
            Native.user_data = callbacks.NativeUserData;
            if (_log != null)
            {
                _self = GCHandle.Alloc(this);
                Native.log = LogTrampolinePointer;
                Native.user_data = GCHandle.ToIntPtr(_self);
            }
            _references = 1;  // the creator's, handed to the scene's handle on success
        }

        /// <summary>The state for these callbacks, or null when there are none.</summary>
        internal static CallbackState Create(Callbacks callbacks)
        {
            return callbacks == null ? null : new CallbackState(callbacks);
        }

        internal void AddReference()
        {
            Interlocked.Increment(ref _references);
        }

        /// <summary>Drops one reference; the last one frees the GCHandle.</summary>
        internal void Release()
        {
            if (Interlocked.Decrement(ref _references) == 0 && _self.IsAllocated) _self.Free();
        }

        [MonoPInvokeCallback(typeof(NativeLogFunction))]
        private static void ForwardLog(IntPtr userData, int level, IntPtr message)
        {
            try
            {
                var state = (CallbackState)GCHandle.FromIntPtr(userData).Target;
                state._log((LogLevel)level, Utf8.FromNative(message));
            }
            catch (Exception)
            {
                // A managed exception must not unwind through the C library's frames.
            }
        }
    }

    /// <summary>
    /// Marks a static method called from native code, for ahead-of-time compilers (Unity's
    /// IL2CPP, Xamarin) that recognise the attribute by this name.
    /// </summary>
    [AttributeUsage(AttributeTargets.Method)]
    internal sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        internal MonoPInvokeCallbackAttribute(Type delegateType)
        {
            DelegateType = delegateType;
        }

        internal Type DelegateType { get; private set; }
    }
}
