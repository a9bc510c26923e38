// SPDX-License-Identifier: Apache-2.0
// The C handles as SafeHandles. The marshaller (or a HandleLease) holds a reference while
// a call runs, so the C destroy runs only after every call in flight has returned: closing
// a scene while another thread steps it ends that step first, and every later call throws
// ObjectDisposedException instead of reaching freed memory. A finalizer destroys a handle
// that was never disposed.
using System;
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>
    /// A handle of the C API with the scene's callbacks it keeps alive (a scene's own, or the
    /// one its skin shares: C may call them until the last of them is destroyed).
    /// </summary>
    internal abstract class EnteronHandle : SafeHandle
    {
        internal CallbackState Callbacks;

        protected EnteronHandle() : base(IntPtr.Zero, true)
        {
        }

        public override bool IsInvalid
        {
            get { return handle == IntPtr.Zero; }
        }

        /// <summary>The C destroy function of this kind of handle.</summary>
        protected abstract void Destroy(IntPtr pointer);

        protected override bool ReleaseHandle()
        {
            Destroy(handle);
            if (Callbacks != null) Callbacks.Release();
            return true;
        }
    }

    /// <summary>An ent_scene*.</summary>
    internal sealed class SceneHandle : EnteronHandle
    {
        protected override void Destroy(IntPtr pointer)
        {
            NativeMethods.ent_scene_destroy(pointer);
        }
    }

    /// <summary>
    /// An ent_skin*. A skin shares its scene's published snapshots in C, so it keeps
    /// working after its scene is disposed; it holds only the scene's callbacks alive.
    /// </summary>
    internal sealed class SkinHandle : EnteronHandle
    {
        protected override void Destroy(IntPtr pointer)
        {
            NativeMethods.ent_skin_destroy(pointer);
        }
    }

    /// <summary>
    /// An ent_exposure*: a target prepared for one scene. It holds nothing of the scene (C
    /// keeps no reference to it), so it needs no callbacks; its queries pass both handles,
    /// so neither the scene nor the exposure is destroyed under a query.
    /// </summary>
    internal sealed class ExposureHandle : EnteronHandle
    {
        protected override void Destroy(IntPtr pointer)
        {
            NativeMethods.ent_exposure_destroy(pointer);
        }
    }

    /// <summary>
    /// A reference on a handle for longer than one call (a skin's mesh view is read after
    /// ent_skin_mesh returns): <c>using (var lease = new HandleLease(handle)) { ... lease.Pointer ... }</c>.
    /// A struct: taking one allocates nothing.
    /// </summary>
    internal struct HandleLease : IDisposable
    {
        private readonly SafeHandle _handle;
        private bool _added;

        /// <summary>Throws ObjectDisposedException when the handle is closed.</summary>
        internal HandleLease(SafeHandle handle)
        {
            _handle = handle;
            _added = false;
            handle.DangerousAddRef(ref _added);
        }

        internal IntPtr Pointer
        {
            get { return _handle.DangerousGetHandle(); }
        }

        public void Dispose()
        {
            if (_added) _handle.DangerousRelease();
            _added = false;
        }
    }
}
