// SPDX-License-Identifier: Apache-2.0
// The bowel's surface as a Unity Mesh, updated every frame (LateUpdate, on the main thread)
// from the last state the scene published: the skin reads a snapshot, so the physics
// thread never waits for it. With a stable topology (tube and convolution skins, the
// default) only the vertex buffers change from frame to frame: positions, normals,
// tangents and texture coordinates are set every frame, the indices only when the skin
// says its topology changed (docs/skinning.md, "A mesh a GPU can keep"). The arrays grow
// when the mesh does and are reused otherwise: a frame allocates nothing.
using UnityEngine;
using UnityEngine.Rendering;

namespace Enteron.Unity
{
    /// <summary>
    /// Draws an <see cref="EnteronScene"/>'s bowel. Put it on the scene's object or on a
    /// child at its origin: the mesh is in the scene's frame.
    /// </summary>
    [RequireComponent(typeof(MeshFilter))]
    public sealed unsafe class EnteronSkinRenderer : MonoBehaviour
    {
        [Tooltip("The scene to draw (default: the EnteronScene on this object or a parent).")]
        public EnteronScene scene;

        [Tooltip("Convolution (the default) or tube keep their topology while the bowel moves; point skeleton does not.")]
        public SkinMethod method = SkinMethod.Convolution;

        [Tooltip("Vertices around each ring (tube, convolution).")]
        public int segments = 16;

        [Tooltip("Arc length between rings, in bowel radii (tube, convolution).")]
        public float ringSpacingRadii = 0.5f;

        /// <summary>The skin (null before Start).</summary>
        public Skin Skin { get; private set; }

        /// <summary>The mesh this component fills.</summary>
        public Mesh Mesh { get; private set; }

        /// <summary>The mesh's state after the last frame's update.</summary>
        public MeshInfo LastMesh { get; private set; }

        /// <summary>Times the indices were uploaded (once, with a stable topology).</summary>
        public int IndexUploads { get; private set; }

        private Vector3[] _positions = new Vector3[0];
        private Vector3[] _normals = new Vector3[0];
        private Vector4[] _tangents = new Vector4[0];
        private Vector2[] _uv = new Vector2[0];
        private int[] _indices = new int[0];
        private float[] _scratch = new float[0];  // 3 floats a vertex: tangents, then u and v
        private ulong _uploadedTopology = ulong.MaxValue;

        private void Start()
        {
            if (scene == null) scene = GetComponentInParent<EnteronScene>();
            if (scene == null || scene.Scene == null)
            {
                Debug.LogError("EnteronSkinRenderer " + name + ": no loaded EnteronScene on this object or a parent", this);
                enabled = false;
                return;
            }
            SkinDesc desc = SkinDesc.Default(method);
            desc.segments = (uint)segments;
            desc.ring_spacing_radii = ringSpacingRadii;
            Skin = new Skin(scene.Scene, desc);
            Mesh = new Mesh();
            Mesh.name = "Enteron bowel";
            Mesh.MarkDynamic();
            GetComponent<MeshFilter>().sharedMesh = Mesh;
        }

        private void LateUpdate()
        {
            if (Skin != null) UpdateMesh();
        }

        private void OnDestroy()
        {
            if (Skin != null) Skin.Dispose();
            Skin = null;
            if (Mesh != null) Destroy(Mesh);
        }

        /// <summary>Rebuilds the skin from the last published state and copies it into <see cref="Mesh"/>.</summary>
        public void UpdateMesh()
        {
            Skin.Update();
            MeshInfo info = Skin.Mesh;
            int vertices = info.VertexCount;
            Grow(ref _positions, vertices);
            Grow(ref _normals, vertices);
            Grow(ref _tangents, vertices);
            Grow(ref _uv, vertices);
            Grow(ref _scratch, 3 * vertices);
            fixed (Vector3* positions = _positions) Skin.CopyPositions((float*)positions, 3 * _positions.Length);
            fixed (Vector3* normals = _normals) Skin.CopyNormals((float*)normals, 3 * _normals.Length);
            Vector3 lowest = new Vector3(float.MaxValue, float.MaxValue, float.MaxValue), highest = -lowest;
            for (int i = 0; i < vertices; ++i)
            {
                Vector3 p = _positions[i];
                p = new Vector3(p.x, p.z, p.y);  // EnteronSpace: y and z swap
                _positions[i] = p;
                lowest = Vector3.Min(lowest, p);
                highest = Vector3.Max(highest, p);
                Vector3 n = _normals[i];
                _normals[i] = new Vector3(n.x, n.z, n.y);
            }
            // Enteron's bitangent tangent x normal runs along increasing v; mirrored into Unity's
            // frame it is normal x tangent, Unity's bitangent with w = +1.
            Skin.CopyTangents(_scratch);
            for (int i = 0; i < vertices; ++i)
                _tangents[i] = new Vector4(_scratch[3 * i], _scratch[3 * i + 2], _scratch[3 * i + 1], 1f);
            fixed (float* scratch = _scratch)
            {
                Skin.CopyAxisU(scratch, vertices);
                Skin.CopyAroundV(scratch + vertices, vertices);
            }
            for (int i = 0; i < vertices; ++i) _uv[i] = new Vector2(_scratch[i], _scratch[vertices + i]);

            bool newTopology = info.TopologySerial != _uploadedTopology;
            if (newTopology)
            {
                Grow(ref _indices, 3 * info.TriangleCount);
                Skin.CopyIndices(_indices);
                Mesh.Clear();
                Mesh.indexFormat = vertices > 65535 ? IndexFormat.UInt32 : IndexFormat.UInt16;
            }
            Mesh.SetVertices(_positions, 0, vertices);
            Mesh.SetNormals(_normals, 0, vertices);
            Mesh.SetTangents(_tangents, 0, vertices);
            Mesh.SetUVs(0, _uv, 0, vertices);
            if (newTopology)
            {
                Mesh.SetIndices(_indices, 0, 3 * info.TriangleCount, MeshTopology.Triangles, 0, false, 0);
                _uploadedTopology = info.TopologySerial;
                ++IndexUploads;
            }
            Mesh.bounds = new Bounds((lowest + highest) * 0.5f, highest - lowest);
            LastMesh = info;
        }

        private static void Grow<T>(ref T[] array, int length)
        {
            if (array.Length < length) array = new T[length + length / 8];  // headroom: a ring more or less
        }
    }
}
