// SPDX-License-Identifier: Apache-2.0
using System;
using System.Threading;

namespace Enteron
{
    /// <summary>
    /// The bowel's surface as a closed triangle mesh, for rendering (ent_skin; docs/skinning.md).
    /// <code>
    /// using (var skin = new Skin(scene, SkinDesc.Default()))      // render thread
    /// {
    ///     skin.Update();                                          // from the last published step
    ///     MeshInfo mesh = skin.Mesh;
    ///     skin.CopyPositions(positions);                          // float[3 * mesh.VertexCount]
    ///     if (mesh.TopologyChanged) skin.CopyIndices(indices);    // only then
    /// }
    /// </code>
    /// The mesh is copied into the caller's arrays (float[], int[] or native memory): no
    /// view of the library's buffers escapes, so nothing can read them after the next update
    /// or the skin's disposal. Update and the copies allocate nothing on the managed heap
    /// (and the library reuses its buffers). A skin may outlive its scene: it keeps the last
    /// state the scene published.
    /// Threads, as in C: a skin is used by one thread at a time (which may differ from the
    /// stepping thread); a call made while another thread is in a call on the same skin
    /// throws InvalidOperationException instead of racing. <see cref="Dispose"/> may come
    /// from any thread: a call in flight ends first.
    /// </summary>
    public sealed unsafe class Skin : IDisposable
    {
        private readonly SkinHandle _handle;
        private volatile bool _disposed;
        private int _inUse;  // 1 while a call runs: the C skin must not be used by two threads at once

        /// <summary>A skin of the scene (ent_skin_create); its mesh is empty until the first <see cref="Update"/>.</summary>
        /// <exception cref="EnteronException">InvalidArgument (a knob out of range: the message names it).</exception>
        public Skin(Scene scene, SkinDesc desc)
        {
            Arguments.NotNull(scene, "scene");
            // The skin holds the scene's callbacks too (C may call them until the last skin
            // goes); taken under a lease, so that the scene cannot drop its own meanwhile.
            SceneHandle sceneHandle = scene.Handle;
            using (var lease = new HandleLease(sceneHandle))
            {
                CallbackState callbacks = sceneHandle.Callbacks;
                if (callbacks != null) callbacks.AddReference();
                Status status = NativeMethods.ent_skin_create(sceneHandle, ref desc, out _handle);
                if (status != Status.Ok)
                {
                    string message = Library.LastError;
                    _handle.Dispose();
                    if (callbacks != null) callbacks.Release();
                    throw new EnteronException(status, "ent_skin_create", message);
                }
                _handle.Callbacks = callbacks;
            }
        }

        /// <summary>Destroys the skin (ent_skin_destroy) once no call on it runs; any thread, more than once.</summary>
        public void Dispose()
        {
            _disposed = true;
            _handle.Dispose();
        }

        /// <summary>True once <see cref="Dispose"/> was called.</summary>
        public bool IsDisposed
        {
            get { return _disposed; }
        }

        /// <summary>The handle for a call; throws ObjectDisposedException once Dispose was called (see Scene.Handle).</summary>
        private SkinHandle Handle
        {
            get
            {
                if (_disposed) throw new ObjectDisposedException("Enteron.Skin", "the skin was disposed");
                return _handle;
            }
        }

        /// <summary>
        /// Rebuilds the mesh from the scene's last published state (ent_skin_update); safe
        /// while another thread steps the scene, and after the scene is disposed.
        /// </summary>
        public void Update()
        {
            Enter("Update");
            try
            {
                EnteronException.Check(NativeMethods.ent_skin_update(Handle), "ent_skin_update");
            }
            finally
            {
                Exit();
            }
        }

        /// <summary>The counts, time and topology flags of the current mesh (ent_skin_mesh).</summary>
        public MeshInfo Mesh
        {
            get { return Copy(Attribute.None, null, 0, "Mesh"); }
        }

        /// <summary>Copies the vertex positions, x y z each, m (3 x VertexCount floats).</summary>
        public MeshInfo CopyPositions(float[] positionsXyz)
        {
            Arguments.NotNull(positionsXyz, "positionsXyz");
            fixed (float* destination = positionsXyz)
                return Copy(Attribute.Positions, destination, positionsXyz.Length, "CopyPositions");
        }

        /// <summary>As <see cref="CopyPositions(float[])"/> into native memory of capacity floats.</summary>
        public MeshInfo CopyPositions(float* positionsXyz, int capacity)
        {
            return Copy(Attribute.Positions, positionsXyz, capacity, "CopyPositions");
        }

        /// <summary>Copies the unit normals, pointing out of the bowel (3 x VertexCount floats).</summary>
        public MeshInfo CopyNormals(float[] normalsXyz)
        {
            Arguments.NotNull(normalsXyz, "normalsXyz");
            fixed (float* destination = normalsXyz)
                return Copy(Attribute.Normals, destination, normalsXyz.Length, "CopyNormals");
        }

        /// <summary>As <see cref="CopyNormals(float[])"/> into native memory of capacity floats.</summary>
        public MeshInfo CopyNormals(float* normalsXyz, int capacity)
        {
            return Copy(Attribute.Normals, normalsXyz, capacity, "CopyNormals");
        }

        /// <summary>Copies the unit tangents along increasing u (3 x VertexCount floats).</summary>
        public MeshInfo CopyTangents(float[] tangentsXyz)
        {
            Arguments.NotNull(tangentsXyz, "tangentsXyz");
            fixed (float* destination = tangentsXyz)
                return Copy(Attribute.Tangents, destination, tangentsXyz.Length, "CopyTangents");
        }

        /// <summary>As <see cref="CopyTangents(float[])"/> into native memory of capacity floats.</summary>
        public MeshInfo CopyTangents(float* tangentsXyz, int capacity)
        {
            return Copy(Attribute.Tangents, tangentsXyz, capacity, "CopyTangents");
        }

        /// <summary>Copies each vertex's u in [0, 1] along the axis (VertexCount floats): a texture coordinate.</summary>
        public MeshInfo CopyAxisU(float[] axisU)
        {
            Arguments.NotNull(axisU, "axisU");
            fixed (float* destination = axisU) return Copy(Attribute.AxisU, destination, axisU.Length, "CopyAxisU");
        }

        /// <summary>As <see cref="CopyAxisU(float[])"/> into native memory of capacity floats.</summary>
        public MeshInfo CopyAxisU(float* axisU, int capacity)
        {
            return Copy(Attribute.AxisU, axisU, capacity, "CopyAxisU");
        }

        /// <summary>Copies each vertex's v in [0, 1) around the tube (VertexCount floats): a texture coordinate.</summary>
        public MeshInfo CopyAroundV(float[] aroundV)
        {
            Arguments.NotNull(aroundV, "aroundV");
            fixed (float* destination = aroundV)
                return Copy(Attribute.AroundV, destination, aroundV.Length, "CopyAroundV");
        }

        /// <summary>As <see cref="CopyAroundV(float[])"/> into native memory of capacity floats.</summary>
        public MeshInfo CopyAroundV(float* aroundV, int capacity)
        {
            return Copy(Attribute.AroundV, aroundV, capacity, "CopyAroundV");
        }

        /// <summary>
        /// Copies the triangles' vertex indices, 3 per triangle, counter-clockwise seen from
        /// outside (3 x TriangleCount ints, each below VertexCount). Needed again only when
        /// <see cref="MeshInfo.TopologyChanged"/>.
        /// </summary>
        public MeshInfo CopyIndices(int[] indices)
        {
            Arguments.NotNull(indices, "indices");
            fixed (int* destination = indices) return Copy(Attribute.Indices, destination, indices.Length, "CopyIndices");
        }

        /// <summary>As <see cref="CopyIndices(int[])"/> into native memory of capacity 32-bit indices.</summary>
        public MeshInfo CopyIndices(uint* indices, int capacity)
        {
            return Copy(Attribute.Indices, indices, capacity, "CopyIndices");
        }

        /// <summary>How close the mesh is to the ideal tube (ent_skin_metrics). Costs more than an update: not every frame.</summary>
        public SkinMetrics GetMetrics()
        {
            Enter("GetMetrics");
            try
            {
                var metrics = new SkinMetrics();
                metrics.struct_size = StructSize<SkinMetrics>.Value;
                EnteronException.Check(NativeMethods.ent_skin_metrics(Handle, ref metrics), "ent_skin_metrics");
                return metrics;
            }
            finally
            {
                Exit();
            }
        }

        // ---- the mesh view, read under a lease and the one-thread guard -------------------------

        private enum Attribute
        {
            None,
            Positions,
            Normals,
            Tangents,
            AxisU,
            AroundV,
            Indices,
        }

        /// <summary>
        /// Takes the view (ent_skin_mesh) and copies one attribute out of it while the skin can
        /// neither update (the guard) nor be destroyed (the lease). Every attribute is made of
        /// 4-byte numbers (float, uint32).
        /// </summary>
        private MeshInfo Copy(Attribute attribute, void* destination, int capacity, string operation)
        {
            if (capacity < 0) throw new ArgumentOutOfRangeException("capacity", capacity, "must be >= 0");
            Enter(operation);
            try
            {
                using (var lease = new HandleLease(Handle))
                {
                    var view = new MeshView();
                    view.struct_size = StructSize<MeshView>.Value;
                    EnteronException.Check(NativeMethods.ent_skin_mesh(lease.Pointer, ref view), "ent_skin_mesh");
                    IntPtr source;
                    long count;
                    switch (attribute)
                    {
                        case Attribute.Positions: source = view.positions_xyz_m; count = 3L * view.vertex_count; break;
                        case Attribute.Normals: source = view.normals_xyz; count = 3L * view.vertex_count; break;
                        case Attribute.Tangents: source = view.tangents_xyz; count = 3L * view.vertex_count; break;
                        case Attribute.AxisU: source = view.axis_u; count = view.vertex_count; break;
                        case Attribute.AroundV: source = view.around_v; count = view.vertex_count; break;
                        case Attribute.Indices: source = view.indices; count = 3L * view.triangle_count; break;
                        default: source = IntPtr.Zero; count = 0; break;
                    }
                    if (count > capacity)
                        throw new ArgumentException(string.Format(
                            "Enteron.Skin.{0}: the mesh has {1} numbers of this attribute ({2} vertices, {3} triangles); " +
                            "the destination holds {4}", operation, count, view.vertex_count, view.triangle_count, capacity));
                    if (count > 0)
                    {
                        if (destination == null) throw new ArgumentNullException("destination");
                        Buffer.MemoryCopy((void*)source, destination, 4L * capacity, 4L * count);
                    }
                    return new MeshInfo(ref view);
                }
            }
            finally
            {
                Exit();
            }
        }

        private void Enter(string operation)
        {
            if (Interlocked.CompareExchange(ref _inUse, 1, 0) != 0)
                throw new InvalidOperationException("Enteron.Skin." + operation + ": another thread is using this skin; " +
                                                    "a skin is used by one thread at a time (one skin per thread, or a lock)");
        }

        private void Exit()
        {
            Volatile.Write(ref _inUse, 0);
        }
    }
}
