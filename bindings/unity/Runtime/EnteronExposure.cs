// SPDX-License-Identifier: Apache-2.0
// How much of a target the bowel leaves in sight from the laparoscope's camera (is the
// area cleared?), measured every frame (LateUpdate, on the main thread, after the scripts
// moved the camera) from the last state the scene published: the query reads a snapshot,
// so the physics thread never waits for it. The target is a mesh's triangles, either fixed
// in the scene (obstacle -1: where the MeshFilter is at Start) or on an organ (an obstacle's
// index: the mesh's own coordinates are the organ's frame, as the sample's organ objects
// hold them, and the target moves with the organ). Prepared once in Start (that allocates);
// a frame allocates nothing. A query costs about 1 us of CPU per sight line, triangles x
// samplesPerEdge^2 of them (docs/scoring-and-state.md of the project).
using System;
using UnityEngine;

namespace Enteron.Unity
{
    /// <summary>The fraction of a target mesh the bowel leaves in sight from a viewpoint (docs: Documentation~/enteron.md).</summary>
    public sealed class EnteronExposure : MonoBehaviour
    {
        [Tooltip("The scene (default: the EnteronScene on this object or a parent).")]
        public EnteronScene scene;

        [Tooltip("The target: its mesh's triangles (default: the MeshFilter on this object).")]
        public MeshFilter target;

        [Tooltip("-1: the target stays where it is at Start. An organ's obstacle index: the mesh is in that organ's frame and moves with it.")]
        public int obstacle = -1;

        [Tooltip("The eye: the laparoscope's camera.")]
        public Transform viewpoint;

        [Tooltip("Each triangle's edge cut into this many parts: samplesPerEdge^2 sight lines a triangle, about 1 us each, every frame.")]
        public int samplesPerEdge = 2;

        [Tooltip("The most spans of the bowel (the loops that hide the target) kept each frame.")]
        public int spanCapacity = 8;

        /// <summary>The prepared target (null before Start or when it could not be made).</summary>
        public Exposure Exposure { get; private set; }

        /// <summary>The target's area seen over its whole area, 0 to 1, at the last frame.</summary>
        public float VisibleFraction { get; private set; }

        /// <summary>The last frame's answer: visible_fraction, span_count, samples, the state's time_s and steps.</summary>
        public ExposureResult Result { get; private set; }

        /// <summary>[first u, last u] of each span of the bowel that hides part of the target (u in [0, 1] along it); the first min(Result.span_count, spanCapacity) pairs are this frame's.</summary>
        public double[] SpansU { get; private set; }

        /// <summary>The fraction of the target each of those spans hides: move the largest first.</summary>
        public double[] SpanHiddenFractions { get; private set; }

        /// <summary>The fraction seen of each triangle of the target mesh, 0 to 1 (to paint it).</summary>
        public double[] TriangleVisible { get; private set; }

        private void Start()
        {
            if (scene == null) scene = GetComponentInParent<EnteronScene>();
            if (target == null) target = GetComponent<MeshFilter>();
            string missing = scene == null || scene.Scene == null ? "no loaded EnteronScene on this object or a parent"
                           : target == null || target.sharedMesh == null ? "no target mesh (a MeshFilter here, or set target)"
                           : viewpoint == null ? "no viewpoint (set it to the laparoscope's camera)"
                           : null;
            if (missing != null)
            {
                Fail(missing);
                return;
            }
            Vector3[] vertices = target.sharedMesh.vertices;
            int[] indices = target.sharedMesh.triangles;
            if (indices.Length == 0)
            {
                Fail("the target mesh has no triangles");
                return;
            }
            var points = new double[3 * vertices.Length];
            for (int v = 0; v < vertices.Length; ++v)
            {
                Vector3 p = obstacle >= 0
                                ? vertices[v]  // the organ's frame
                                : scene.transform.InverseTransformPoint(target.transform.TransformPoint(vertices[v]));
                Vec3 e = EnteronSpace.ToEnteron(p);
                points[3 * v] = e.X;
                points[3 * v + 1] = e.Y;
                points[3 * v + 2] = e.Z;
            }
            var triangles = new uint[indices.Length];
            for (int i = 0; i < indices.Length; ++i) triangles[i] = (uint)indices[i];
            ExposureDesc desc = ExposureDesc.Default();
            desc.samples_per_edge = (uint)Math.Max(0, samplesPerEdge);  // the library says which values it takes
            desc.obstacle = obstacle >= 0 ? obstacle : Scene.NoObstacle;
            try
            {
                Exposure = new Exposure(scene.Scene, desc, points, triangles);
            }
            catch (EnteronException error)
            {
                Fail(error.Message);
                return;
            }
            SpansU = new double[2 * Math.Max(0, spanCapacity)];
            SpanHiddenFractions = new double[Math.Max(0, spanCapacity)];
            TriangleVisible = new double[Exposure.ElementCount];
        }

        private void LateUpdate()
        {
            if (Exposure != null) Measure();
        }

        private void OnDestroy()
        {
            if (Exposure != null) Exposure.Dispose();
            Exposure = null;
        }

        /// <summary>Measures from the viewpoint's position now (main thread: Transforms live there).</summary>
        public void Measure()
        {
            Vec3 eye = EnteronSpace.ToEnteron(scene.transform.InverseTransformPoint(viewpoint.position));
            try
            {
                Result = Exposure.Measure(eye, SpansU, SpanHiddenFractions, null, TriangleVisible);
                VisibleFraction = (float)Result.visible_fraction;
            }
            catch (EnteronException error)
            {
                Fail(error.Message);  // the organ was removed
            }
            catch (ObjectDisposedException error)
            {
                Fail(error.Message);  // the scene is gone
            }
        }

        private void Fail(string why)
        {
            Debug.LogError("EnteronExposure " + name + ": " + why, this);
            enabled = false;
        }
    }
}
