// SPDX-License-Identifier: Apache-2.0
// The abdomen scene in Unity (examples/scenes/abdomen.json): the 6 m small bowel held by its
// mesentery among organ meshes (the abdominal wall, the liver, the stomach), stepped at
// 1 kHz on a physics thread, drawn every frame; a retractor lifts the liver 4 cm between 1
// and 1.5 s and the scene's grasper goes down into the coils between 1.5 and 2.5 s, the
// motion of examples/abdomen_motion.h. Put this component on an empty GameObject and press
// Play: it builds the rest. Untick playTheScript to move the "Grasper" yourself (its
// Transform, in the Scene view) and watch its force in the Inspector.
using System;
using System.IO;
using UnityEngine;
using Enteron;
using Enteron.Unity;

namespace Enteron.Samples
{
    /// <summary>Builds and plays the abdomen scene (Samples~/Abdomen/README.md).</summary>
    public sealed class AbdomenSample : MonoBehaviour, IEnteronStepListener
    {
        [Tooltip("abdomen.json (its organs/ folder beside it); empty: the copy imported with this sample.")]
        public string sceneFile = "";

        [Tooltip("Lift the liver and move the grasper as examples/abdomen_motion.h does.")]
        public bool playTheScript = true;

        /// <summary>The liver's displacement from its pose in the file: t (s), dx, dy, dz (m, Enteron's frame), as abdomen_motion.h.</summary>
        public static readonly double[] LiverKeys = { 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 0.04 };

        /// <summary>The grasper's tip: t (s), x, y, z (m, Enteron's frame), as abdomen_motion.h.</summary>
        public static readonly double[] ToolKeys = { 0.0, -0.1, -0.05, 0.3, 1.5, -0.06, -0.05, 0.3, 2.5, -0.06, -0.05, -0.11 };

        /// <summary>The liver: obstacle 1 in the file's order (wall, liver, stomach).</summary>
        public const int Liver = 1;

        /// <summary>The scene component this sample made.</summary>
        public EnteronScene Scene { get; private set; }

        /// <summary>The grasper (the file's tool 0).</summary>
        public EnteronTool Grasper { get; private set; }

        private Transform[] _organs = new Transform[0];
        private Vec3 _liverStart;
        private Quat _liverOrientation;

        private void Awake()
        {
            string file = string.IsNullOrEmpty(sceneFile) ? FindImportedScene() : sceneFile;
            if (file == null)
            {
                Debug.LogError("AbdomenSample: abdomen.json not found under Assets; set sceneFile", this);
                enabled = false;
                return;
            }
            var root = new GameObject("Enteron abdomen");
            root.SetActive(false);  // Awake waits for SetActive: the file name first
            root.transform.SetParent(transform, false);
            Scene = root.AddComponent<EnteronScene>();
            Scene.sceneFile = Path.GetFullPath(file);
            root.SetActive(true);  // loads it: the organs' distance fields take about a second
            if (Scene.Scene == null)
            {
                enabled = false;
                return;
            }

            var bowel = new GameObject("Bowel");
            bowel.transform.SetParent(root.transform, false);
            bowel.AddComponent<MeshFilter>();
            bowel.AddComponent<MeshRenderer>().sharedMaterial = Lit(new Color(0.85f, 0.45f, 0.45f, 1f));
            bowel.AddComponent<EnteronSkinRenderer>();

            // The organs as the library holds them: read before the physics thread starts
            // (in EnteronScene.Start), as ent_obstacle_mesh asks.
            _organs = new Transform[Scene.Scene.ObstacleCount];
            for (int i = 0; i < _organs.Length; ++i) _organs[i] = Organ(root.transform, i);
            Scene.Scene.GetObstaclePose(Liver, out _liverStart, out _liverOrientation);

            var grasper = new GameObject("Grasper");
            grasper.transform.SetParent(root.transform, false);
            grasper.transform.localPosition = EnteronSpace.ToUnity(At(ToolKeys, 0));
            Grasper = grasper.AddComponent<EnteronTool>();
            Grasper.toolId = 0;
            GameObject shaft = GameObject.CreatePrimitive(PrimitiveType.Cylinder);  // 2 units high, centred
            shaft.transform.SetParent(grasper.transform, false);
            shaft.transform.localScale = new Vector3(0.01f, 0.15f, 0.01f);       // the file's 5 mm radius, 0.3 m
            shaft.transform.localPosition = new Vector3(0f, 0.15f, 0f);          // rising from the tip
            Scene.AddListener(this);
        }

        private void Update()
        {
            if (Scene == null || Scene.Scene == null) return;
            for (int i = 0; i < _organs.Length; ++i)
            {
                if (_organs[i] == null) continue;
                Vec3 position;
                Quat orientation;
                Scene.Scene.GetObstaclePose(i, out position, out orientation);  // a query: never waits for the step
                _organs[i].localPosition = EnteronSpace.ToUnity(position);
                _organs[i].localRotation = EnteronSpace.ToUnity(orientation);
            }
            if (playTheScript) Grasper.transform.localPosition = EnteronSpace.ToUnity(At(ToolKeys, SimulatedTime()));
        }

        /// <summary>The retractor, on the stepping thread before each step (a driving call belongs there).</summary>
        public void BeforeStep(Scene scene)
        {
            if (!playTheScript) return;
            Vec3 lift = At(LiverKeys, SimulatedTime() + Scene.timestep);
            scene.SetObstaclePose(Liver, _liverStart + lift, _liverOrientation);
        }

        private void OnDestroy()
        {
            if (Scene != null) Scene.RemoveListener(this);
        }

        private double SimulatedTime()
        {
            return Scene.Steps * Scene.timestep;
        }

        /// <summary>The key path (t, x, y, z rows) at time t: linear between keys, held after the last.</summary>
        public static Vec3 At(double[] keys, double t)
        {
            int last = keys.Length / 4 - 1;
            for (int k = 0; k < last; ++k)
            {
                if (t > keys[4 * (k + 1)]) continue;
                double a = Math.Max(0.0, (t - keys[4 * k]) / (keys[4 * (k + 1)] - keys[4 * k]));
                return new Vec3(keys[4 * k + 1] + a * (keys[4 * k + 5] - keys[4 * k + 1]),
                                keys[4 * k + 2] + a * (keys[4 * k + 6] - keys[4 * k + 2]),
                                keys[4 * k + 3] + a * (keys[4 * k + 7] - keys[4 * k + 3]));
            }
            return new Vec3(keys[4 * last + 1], keys[4 * last + 2], keys[4 * last + 3]);
        }

        /// <summary>A mesh obstacle as a GameObject whose mesh is in the obstacle's frame.</summary>
        private Transform Organ(Transform parent, int obstacle)
        {
            int vertexCount, triangleCount;
            try
            {
                Scene.Scene.GetObstacleMeshCounts(obstacle, out vertexCount, out triangleCount);
            }
            catch (EnteronException)
            {
                return null;  // not a mesh
            }
            var xyz = new double[3 * vertexCount];
            var triangles = new uint[3 * triangleCount];
            Scene.Scene.CopyObstacleMesh(obstacle, xyz, triangles);
            var vertices = new Vector3[vertexCount];
            for (int v = 0; v < vertexCount; ++v)
                vertices[v] = EnteronSpace.ToUnity(new Vec3(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
            var indices = new int[3 * triangleCount];
            for (int i = 0; i < indices.Length; ++i) indices[i] = (int)triangles[i];
            var mesh = new Mesh();
            mesh.name = "Enteron obstacle " + obstacle;
            mesh.indexFormat = vertexCount > 65535 ? UnityEngine.Rendering.IndexFormat.UInt32 : UnityEngine.Rendering.IndexFormat.UInt16;
            mesh.SetVertices(vertices, 0, vertexCount);
            mesh.SetIndices(indices, 0, indices.Length, MeshTopology.Triangles, 0, true, 0);
            mesh.RecalculateNormals();
            var organ = new GameObject(obstacle == 0 ? "Abdominal wall" : obstacle == Liver ? "Liver" : "Organ " + obstacle);
            organ.transform.SetParent(parent, false);
            organ.AddComponent<MeshFilter>().sharedMesh = mesh;
            organ.AddComponent<MeshRenderer>().sharedMaterial =
                Lit(obstacle == 0 ? new Color(0.9f, 0.8f, 0.75f, 0.15f) : new Color(0.55f, 0.25f, 0.2f, 0.6f));
            return organ.transform;
        }

        private static Material Lit(Color color)
        {
            Shader shader = Shader.Find("Standard");
            if (shader == null) shader = Shader.Find("Universal Render Pipeline/Lit");
            var material = new Material(shader);
            material.color = color;
            return material;
        }

        /// <summary>The abdomen.json imported with the sample (Assets/Samples/Enteron/.../Abdomen/Scenes).</summary>
        private static string FindImportedScene()
        {
            string[] found = Directory.GetFiles(Application.dataPath, "abdomen.json", SearchOption.AllDirectories);
            return found.Length > 0 ? found[0] : null;
        }
    }
}
