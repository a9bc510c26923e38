// SPDX-License-Identifier: Apache-2.0
using System;

namespace Enteron
{
    /// <summary>
    /// How much of a target the bowel leaves in sight from a viewpoint (ent_exposure,
    /// ent_scene_exposure; docs/scoring-and-state.md, "Exposure: is the area cleared?"). The
    /// target is a set of points, or a patch of triangles sampled at samples_per_edge^2 points
    /// each, in the world or on an obstacle's frame (it moves with the organ); only the bowel
    /// hides, a tube of its radius around the last published axis.
    /// <code>
    /// ExposureDesc desc = ExposureDesc.Default();
    /// desc.obstacle = liver;                                              // the patch moves with it
    /// using (var gallbladder = new Exposure(scene, desc, patchXyz, patchTriangles))  // once: it allocates
    /// {
    ///     var spans = new double[8 * 2];
    ///     ExposureResult seen = gallbladder.Measure(scopeTip, spans);    // any thread, allocates nothing
    ///     // seen.visible_fraction; spans[2 k], spans[2 k + 1]: the loops that hide the rest
    /// }
    /// </code>
    /// Threads, as in C: a query reads the scene's last published state, from any thread, also
    /// while the scene steps, and never waits for the step; an exposure measures on one thread
    /// at a time: a <see cref="Measure"/> while another thread measures the same exposure
    /// throws an <see cref="EnteronException"/> with <see cref="Status.Busy"/> and writes
    /// nothing (one exposure per thread). <see cref="Dispose"/>, of the exposure or of its
    /// scene, may come from any thread: a query in flight ends first, and later ones throw
    /// ObjectDisposedException.
    /// </summary>
    public sealed unsafe class Exposure : IDisposable
    {
        private readonly ExposureHandle _handle;
        private volatile bool _disposed;

        /// <summary>
        /// Prepares a target for queries on <paramref name="scene"/> (ent_exposure_create): the
        /// library copies and samples it and sizes the query's work space (about 100 bytes per
        /// sample and per chord of the axis): not on a real-time thread. Any thread.
        /// </summary>
        /// <param name="scene">the scene whose bowel may hide the target; the exposure measures only on it.</param>
        /// <param name="desc">the sampling and the frame (start from <see cref="ExposureDesc.Default"/>).</param>
        /// <param name="pointsXyz">the target's points, or the patch's vertices: x y z each, m, in the frame of desc.obstacle.</param>
        /// <param name="triangles">3 indices into the points each: the target is this patch; null: the points themselves.</param>
        /// <param name="weights">a weight >= 0 per point (no triangles) or per triangle (it multiplies the area); null: all alike.</param>
        /// <exception cref="EnteronException">InvalidArgument (no points, an index past them, a negative weight, a
        /// sampling out of range: the message names the field and the element), NotFound (no such obstacle).</exception>
        public Exposure(Scene scene, ExposureDesc desc, double[] pointsXyz, uint[] triangles = null, double[] weights = null)
        {
            Arguments.NotNull(scene, "scene");
            Arguments.NotNull(pointsXyz, "pointsXyz");
            Arguments.Multiple(pointsXyz.Length, 3, "pointsXyz", "point");
            if (triangles != null) Arguments.Multiple(triangles.Length, 3, "triangles", "triangle");
            bool patch = triangles != null && triangles.Length > 0;
            ElementCount = patch ? triangles.Length / 3 : pointsXyz.Length / 3;
            // C reads one weight per element: a shorter array would be read past its end.
            if (weights != null && weights.Length != ElementCount)
                throw new ArgumentException(string.Format("weights: {0} given for {1} {2}", weights.Length, ElementCount,
                                                          patch ? "triangles" : "points"), "weights");
            Status status;
            fixed (double* points = pointsXyz)
            fixed (uint* indices = triangles)
            fixed (double* pointWeights = weights)
            {
                desc.points_xyz_m = (IntPtr)points;
                desc.point_count = (uint)(pointsXyz.Length / 3);
                desc.triangles = (IntPtr)indices;
                desc.triangle_count = patch ? (uint)ElementCount : 0u;
                desc.weights = (IntPtr)pointWeights;
                status = NativeMethods.ent_exposure_create(scene.Handle, ref desc, out _handle);
            }
            if (status != Status.Ok)
            {
                string message = Library.LastError;  // first, before anything else can fail on this thread
                _handle.Dispose();  // holds no exposure: nothing to destroy
                throw new EnteronException(status, "ent_exposure_create", message);
            }
            Scene = scene;
        }

        /// <summary>The scene the exposure measures on.</summary>
        public Scene Scene { get; private set; }

        /// <summary>The target's elements: its points, or the patch's triangles (the length Measure's elementVisible needs).</summary>
        public int ElementCount { get; private set; }

        /// <summary>
        /// Destroys the prepared target (ent_exposure_destroy) once no query on it runs; any
        /// thread, any time, more than once.
        /// </summary>
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
        private ExposureHandle Handle
        {
            get
            {
                if (_disposed) throw new ObjectDisposedException("Enteron.Exposure", "the exposure was disposed");
                return _handle;
            }
        }

        /// <summary>
        /// How much of the target the bowel leaves in sight from <paramref name="viewpoint_m"/>
        /// (the eye, m, world frame), on the scene's last published state (ent_scene_exposure).
        /// Each array may be null. Allocates nothing; costs about 1 us of CPU per sample.
        /// </summary>
        /// <param name="viewpoint_m">the eye (the laparoscope's tip), m.</param>
        /// <param name="spansU">receives [first u, last u] of each span of the bowel that hides part of the
        /// target, along the bowel; its capacity is Length / 2 spans (span_count may exceed it: then only
        /// the first spans are written).</param>
        /// <param name="spanHiddenFractions">receives the fraction of the target's weight each span hides
        /// (at least as many as spansU holds spans).</param>
        /// <param name="spanIntestines">receives each span's tube, 0 for the scene's one intestine (as many).</param>
        /// <param name="elementVisible">receives the fraction seen of each point or triangle, 0 to 1
        /// (<see cref="ElementCount"/> of them).</param>
        /// <exception cref="EnteronException">InvalidArgument (a non-finite viewpoint), NotFound (the target's
        /// obstacle was removed), Busy (another thread is measuring this exposure). Nothing is written.</exception>
        public ExposureResult Measure(Vec3 viewpoint_m, double[] spansU = null, double[] spanHiddenFractions = null,
                                      int[] spanIntestines = null, double[] elementVisible = null)
        {
            // C trusts the capacity it is given: every span array must hold spansU's spans.
            int spans = spansU == null ? 0 : spansU.Length / 2;
            if (spansU == null && (spanHiddenFractions != null || spanIntestines != null))
                throw new ArgumentException("spanHiddenFractions and spanIntestines need spansU, whose Length / 2 " +
                                            "is the spans' capacity", "spansU");
            if (spanHiddenFractions != null) Arguments.Fits(spans, 1, spanHiddenFractions.Length, "spanHiddenFractions");
            if (spanIntestines != null) Arguments.Fits(spans, 1, spanIntestines.Length, "spanIntestines");
            if (elementVisible != null) Arguments.Fits(ElementCount, 1, elementVisible.Length, "elementVisible");
            var result = new ExposureResult();
            result.struct_size = StructSize<ExposureResult>.Value;
            fixed (double* spanBounds = spansU)
            fixed (double* hidden = spanHiddenFractions)
            fixed (int* tubes = spanIntestines)
            fixed (double* elements = elementVisible)
            {
                result.span_capacity = spanBounds == null ? 0u : (uint)spans;  // an empty array is no buffer
                result.spans_u = (IntPtr)spanBounds;
                result.span_hidden_fractions = (IntPtr)hidden;
                result.span_intestines = (IntPtr)tubes;
                result.element_visible = (IntPtr)elements;
                EnteronException.Check(NativeMethods.ent_scene_exposure(Scene.Handle, Handle, &viewpoint_m, ref result),
                                       "ent_scene_exposure");
            }
            // The arrays are unpinned now.
            result.spans_u = IntPtr.Zero;
            result.span_hidden_fractions = IntPtr.Zero;
            result.span_intestines = IntPtr.Zero;
            result.element_visible = IntPtr.Zero;
            return result;
        }
    }
}
