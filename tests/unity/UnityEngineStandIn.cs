// SPDX-License-Identifier: Apache-2.0
// A STAND-IN FOR UnityEngine, FOR TESTS ONLY: never shipped, never part of the Unity package.
//
// Unity cannot run here, so CI compiles the package's components (bindings/unity/Runtime and
// Samples~) against these few types, with the names and signatures Unity 2020.3 gives them,
// and runs them in NUnit tests (tests/unity/UnityComponentTests.cs). It holds only what the
// components use: a component that uses anything else fails to compile here. The behaviour
// is the least that lets the components run: the life cycle (Awake and OnEnable when a
// component is added to an active object or its object is activated, Start before its
// first Update, OnDisable and OnDestroy on Destroy), transforms without scale, quaternion
// arithmetic, and a Mesh that keeps what it is given. Rendering, serialization, the
// editor, the player loop's timing: none of it. What this proves and what it does not:
// bindings/unity/Documentation~/enteron.md, "What was verified".
using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;

namespace UnityEngine
{
    public class Object
    {
        public string name = "";

        public static void Destroy(Object target)
        {
            var component = target as Component;
            if (component != null)
            {
                component.gameObject.RemoveComponent(component);
                return;
            }
            var gameObject = target as GameObject;
            if (gameObject != null) gameObject.DestroyAll();
        }

        public static implicit operator bool(Object target)
        {
            return !ReferenceEquals(target, null);
        }
    }

    public sealed class GameObject : Object
    {
        private readonly List<Component> _components = new List<Component>();
        private bool _activeSelf = true;
        public readonly Transform transform;

        public GameObject() : this("New Game Object")
        {
        }

        public GameObject(string name)
        {
            this.name = name;
            transform = new Transform();
            transform.Attach(this);
            _components.Add(transform);
            UnityEngineStandIn.Player.Register(this);
        }

        public bool activeSelf
        {
            get { return _activeSelf; }
        }

        public bool activeInHierarchy
        {
            get { return _activeSelf && (transform.parent == null || transform.parent.gameObject.activeInHierarchy); }
        }

        public void SetActive(bool value)
        {
            if (value == _activeSelf) return;
            _activeSelf = value;
            foreach (Component component in _components.ToArray())
                if (value) UnityEngineStandIn.Player.Activate(component);
                else UnityEngineStandIn.Player.Call(component as Behaviour, "OnDisable");
        }

        public T AddComponent<T>() where T : Component, new()
        {
            var component = new T();
            component.Attach(this);
            _components.Add(component);
            if (activeInHierarchy) UnityEngineStandIn.Player.Activate(component);
            return component;
        }

        public T GetComponent<T>() where T : class
        {
            return _components.OfType<T>().FirstOrDefault();
        }

        internal IEnumerable<Component> Components
        {
            get { return _components; }
        }

        internal void RemoveComponent(Component component)
        {
            UnityEngineStandIn.Player.Call(component as Behaviour, "OnDisable");
            UnityEngineStandIn.Player.Call(component as Behaviour, "OnDestroy");
            _components.Remove(component);
        }

        internal void DestroyAll()
        {
            foreach (Transform child in transform.Children.ToArray()) child.gameObject.DestroyAll();
            foreach (Component component in _components.Where(c => !(c is Transform)).ToArray()) RemoveComponent(component);
            transform.SetParent(null, false);
            UnityEngineStandIn.Player.Unregister(this);
        }

        public static GameObject CreatePrimitive(PrimitiveType type)
        {
            var primitive = new GameObject(type.ToString());
            primitive.AddComponent<MeshFilter>().sharedMesh = new Mesh();
            primitive.AddComponent<MeshRenderer>();
            return primitive;
        }
    }

    public class Component : Object
    {
        public GameObject gameObject { get; private set; }

        public Transform transform
        {
            get { return gameObject.transform; }
        }

        internal void Attach(GameObject owner)
        {
            gameObject = owner;
            name = owner.name;
        }

        public T GetComponent<T>() where T : class
        {
            return gameObject.GetComponent<T>();
        }

        public T GetComponentInParent<T>() where T : class
        {
            for (Transform at = transform; at != null; at = at.parent)
            {
                T found = at.gameObject.GetComponent<T>();
                if (found != null) return found;
            }
            return null;
        }
    }

    public class Behaviour : Component
    {
        private bool _enabled = true;

        public bool enabled
        {
            get { return _enabled; }
            set
            {
                if (value == _enabled) return;
                _enabled = value;
                if (UnityEngineStandIn.Player.Awoken(this) && gameObject.activeInHierarchy)
                    UnityEngineStandIn.Player.Call(this, value ? "OnEnable" : "OnDisable");
            }
        }
    }

    public class MonoBehaviour : Behaviour
    {
    }

    public sealed class Transform : Component
    {
        private readonly List<Transform> _children = new List<Transform>();
        public Vector3 localPosition;
        public Quaternion localRotation = Quaternion.identity;
        public Vector3 localScale = new Vector3(1, 1, 1);

        public Transform parent { get; private set; }

        internal IEnumerable<Transform> Children
        {
            get { return _children; }
        }

        public void SetParent(Transform newParent, bool worldPositionStays)
        {
            Vector3 position = this.position;
            Quaternion rotation = this.rotation;
            if (parent != null) parent._children.Remove(this);
            parent = newParent;
            if (parent != null) parent._children.Add(this);
            if (worldPositionStays)
            {
                this.position = position;
                this.rotation = rotation;
            }
        }

        public Vector3 position
        {
            get { return parent == null ? localPosition : parent.rotation * localPosition + parent.position; }
            set { localPosition = parent == null ? value : Quaternion.Inverse(parent.rotation) * (value - parent.position); }
        }

        public Quaternion rotation
        {
            get { return parent == null ? localRotation : parent.rotation * localRotation; }
            set { localRotation = parent == null ? value : Quaternion.Inverse(parent.rotation) * value; }
        }

        public Transform Find(string childName)
        {
            return _children.FirstOrDefault(child => child.gameObject.name == childName);
        }

        public Vector3 TransformPoint(Vector3 point)
        {
            return rotation * point + position;
        }

        public Vector3 InverseTransformPoint(Vector3 point)
        {
            return Quaternion.Inverse(rotation) * (point - position);
        }
    }

    public struct Vector2
    {
        public float x, y;

        public Vector2(float x, float y)
        {
            this.x = x;
            this.y = y;
        }
    }

    public struct Vector3
    {
        public float x, y, z;

        public Vector3(float x, float y, float z)
        {
            this.x = x;
            this.y = y;
            this.z = z;
        }

        public static Vector3 zero
        {
            get { return new Vector3(0, 0, 0); }
        }

        public float magnitude
        {
            get { return (float)Math.Sqrt(x * x + y * y + z * z); }
        }

        public static Vector3 operator +(Vector3 a, Vector3 b) { return new Vector3(a.x + b.x, a.y + b.y, a.z + b.z); }
        public static Vector3 operator -(Vector3 a, Vector3 b) { return new Vector3(a.x - b.x, a.y - b.y, a.z - b.z); }
        public static Vector3 operator -(Vector3 a) { return new Vector3(-a.x, -a.y, -a.z); }
        public static Vector3 operator *(Vector3 a, float s) { return new Vector3(a.x * s, a.y * s, a.z * s); }
        public static Vector3 operator *(float s, Vector3 a) { return a * s; }
        public static Vector3 Min(Vector3 a, Vector3 b) { return new Vector3(Math.Min(a.x, b.x), Math.Min(a.y, b.y), Math.Min(a.z, b.z)); }
        public static Vector3 Max(Vector3 a, Vector3 b) { return new Vector3(Math.Max(a.x, b.x), Math.Max(a.y, b.y), Math.Max(a.z, b.z)); }
        public static float Dot(Vector3 a, Vector3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

        public static Vector3 Cross(Vector3 a, Vector3 b)
        {
            return new Vector3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
        }

        public override string ToString()
        {
            return string.Format(System.Globalization.CultureInfo.InvariantCulture, "({0}, {1}, {2})", x, y, z);
        }
    }

    public struct Vector4
    {
        public float x, y, z, w;

        public Vector4(float x, float y, float z, float w)
        {
            this.x = x;
            this.y = y;
            this.z = z;
            this.w = w;
        }
    }

    public struct Quaternion
    {
        public float x, y, z, w;

        public Quaternion(float x, float y, float z, float w)
        {
            this.x = x;
            this.y = y;
            this.z = z;
            this.w = w;
        }

        public static Quaternion identity
        {
            get { return new Quaternion(0, 0, 0, 1); }
        }

        public static Quaternion Inverse(Quaternion q)
        {
            float n = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
            return new Quaternion(-q.x / n, -q.y / n, -q.z / n, q.w / n);
        }

        public static Quaternion AngleAxis(float degrees, Vector3 axis)
        {
            float half = (float)(degrees * Math.PI / 360.0);
            float s = (float)Math.Sin(half) / axis.magnitude;
            return new Quaternion(axis.x * s, axis.y * s, axis.z * s, (float)Math.Cos(half));
        }

        public static Quaternion operator *(Quaternion a, Quaternion b)
        {
            return new Quaternion(a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                                  a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
                                  a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x,
                                  a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);
        }

        public static Vector3 operator *(Quaternion q, Vector3 v)
        {
            // v + 2 w (u x v) + 2 u x (u x v), u the vector part
            var u = new Vector3(q.x, q.y, q.z);
            Vector3 t = 2f * Vector3.Cross(u, v);
            return v + q.w * t + Vector3.Cross(u, t);
        }
    }

    public struct Matrix4x4
    {
        public float m00, m01, m02, m03, m10, m11, m12, m13, m20, m21, m22, m23, m30, m31, m32, m33;

        public Vector3 MultiplyVector(Vector3 v)
        {
            return new Vector3(m00 * v.x + m01 * v.y + m02 * v.z, m10 * v.x + m11 * v.y + m12 * v.z,
                               m20 * v.x + m21 * v.y + m22 * v.z);
        }
    }

    public struct Color
    {
        public float r, g, b, a;

        public Color(float r, float g, float b, float a)
        {
            this.r = r;
            this.g = g;
            this.b = b;
            this.a = a;
        }
    }

    public struct Bounds
    {
        public Vector3 center, size;

        public Bounds(Vector3 center, Vector3 size)
        {
            this.center = center;
            this.size = size;
        }
    }

    public enum MeshTopology
    {
        Triangles = 0,
    }

    public enum PrimitiveType
    {
        Sphere,
        Capsule,
        Cylinder,
        Cube,
        Plane,
        Quad,
    }

    public sealed class Mesh : Object
    {
        private Vector3[] _vertices = new Vector3[0];
        private Vector3[] _normals = new Vector3[0];
        private Vector4[] _tangents = new Vector4[0];
        private Vector2[] _uv = new Vector2[0];
        private int[] _triangles = new int[0];
        public Bounds bounds;
        public Rendering.IndexFormat indexFormat;

        public int vertexCount
        {
            get { return _vertices.Length; }
        }

        // Unity's getters return copies, as these do.
        public Vector3[] vertices
        {
            get { return (Vector3[])_vertices.Clone(); }
        }

        public Vector3[] normals
        {
            get { return (Vector3[])_normals.Clone(); }
        }

        public Vector4[] tangents
        {
            get { return (Vector4[])_tangents.Clone(); }
        }

        public Vector2[] uv
        {
            get { return (Vector2[])_uv.Clone(); }
        }

        public int[] triangles
        {
            get { return (int[])_triangles.Clone(); }
        }

        public void MarkDynamic()
        {
        }

        public void Clear()
        {
            _vertices = new Vector3[0];
            _normals = new Vector3[0];
            _tangents = new Vector4[0];
            _uv = new Vector2[0];
            _triangles = new int[0];
        }

        public void SetVertices(Vector3[] inVertices, int start, int length)
        {
            if (_triangles.Any(i => i >= length))
                throw new ArgumentException("Mesh.SetVertices: the indices refer to vertices beyond the new count (Unity refuses this too)");
            _vertices = Range(inVertices, start, length);
        }

        public void SetNormals(Vector3[] inNormals, int start, int length)
        {
            _normals = Range(inNormals, start, length);
        }

        public void SetTangents(Vector4[] inTangents, int start, int length)
        {
            _tangents = Range(inTangents, start, length);
        }

        public void SetUVs(int channel, Vector2[] uvs, int start, int length)
        {
            if (channel != 0) throw new ArgumentException("stand-in: only channel 0");
            _uv = Range(uvs, start, length);
        }

        public void SetIndices(int[] indices, int indicesStart, int indicesLength, MeshTopology topology, int submesh,
                               bool calculateBounds, int baseVertex)
        {
            int[] range = Range(indices, indicesStart, indicesLength);
            if (range.Any(i => i < 0 || i + baseVertex >= _vertices.Length))
                throw new ArgumentException("Mesh.SetIndices: an index out of the vertex range (Unity refuses this too)");
            if (indexFormat == Rendering.IndexFormat.UInt16 && _vertices.Length > 65536)
                throw new ArgumentException("Mesh.SetIndices: more than 65536 vertices need IndexFormat.UInt32");
            _triangles = range;
        }

        public void RecalculateNormals()
        {
            _normals = new Vector3[_vertices.Length];
        }

        private static T[] Range<T>(T[] source, int start, int length)
        {
            if (start < 0 || length < 0 || start + length > source.Length)
                throw new ArgumentOutOfRangeException("length", "start and length must lie within the array (Unity checks this too)");
            var copy = new T[length];
            Array.Copy(source, start, copy, 0, length);
            return copy;
        }
    }

    public sealed class MeshFilter : Component
    {
        public Mesh sharedMesh;

        public Mesh mesh
        {
            get { return sharedMesh; }
            set { sharedMesh = value; }
        }
    }

    public sealed class MeshRenderer : Component
    {
        public Material sharedMaterial;
    }

    public sealed class Shader : Object
    {
        public static Shader Find(string name)
        {
            return name == "Standard" ? new Shader { name = name } : null;
        }
    }

    public sealed class Material : Object
    {
        public Color color;

        public Material(Shader shader)
        {
            name = shader == null ? "no shader" : shader.name;
        }
    }

    public sealed class TextAsset : Object
    {
        public TextAsset(string text)
        {
            this.text = text;
        }

        public string text { get; private set; }
    }

    public static class Debug
    {
        public static void Log(object message)
        {
            UnityEngineStandIn.Player.Logged.Add("Log: " + message);
        }

        public static void LogError(object message, Object context)
        {
            UnityEngineStandIn.Player.Logged.Add("Error: " + message);
        }
    }

    public static class Application
    {
        public static string streamingAssetsPath = "";
        public static string dataPath = "";
    }

    public static class Time
    {
        public static float deltaTime = 1f / 60f;
    }

    [AttributeUsage(AttributeTargets.Field)]
    public sealed class TooltipAttribute : Attribute
    {
        public TooltipAttribute(string tooltip)
        {
        }
    }

    [AttributeUsage(AttributeTargets.Class)]
    public sealed class DisallowMultipleComponentAttribute : Attribute
    {
    }

    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public sealed class RequireComponentAttribute : Attribute
    {
        public RequireComponentAttribute(Type type)
        {
        }
    }
}

namespace UnityEngine.Rendering
{
    public enum IndexFormat
    {
        UInt16 = 0,
        UInt32 = 1,
    }
}

namespace UnityEngineStandIn
{
    using UnityEngine;

    /// <summary>The stand-in's player loop, for tests: the life-cycle calls Unity makes by name.</summary>
    public static class Player
    {
        private static readonly List<GameObject> Objects = new List<GameObject>();
        private static readonly HashSet<Component> AwokenComponents = new HashSet<Component>();
        private static readonly HashSet<Component> Started = new HashSet<Component>();

        /// <summary>Debug.Log and Debug.LogError lines.</summary>
        public static readonly List<string> Logged = new List<string>();

        internal static void Register(GameObject gameObject)
        {
            Objects.Add(gameObject);
        }

        internal static void Unregister(GameObject gameObject)
        {
            Objects.Remove(gameObject);
        }

        internal static bool Awoken(Component component)
        {
            return AwokenComponents.Contains(component);
        }

        internal static void Activate(Component component)
        {
            if (!AwokenComponents.Contains(component))
            {
                AwokenComponents.Add(component);
                Call(component as Behaviour, "Awake");
            }
            var behaviour = component as Behaviour;
            if (behaviour != null && behaviour.enabled) Call(behaviour, "OnEnable");
        }

        internal static void Call(Behaviour behaviour, string method)
        {
            if (behaviour == null) return;
            MethodInfo found = behaviour.GetType().GetMethod(method, BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic);
            if (found != null && found.GetParameters().Length == 0) found.Invoke(behaviour, null);
        }

        /// <summary>One frame: Start for the components that have not started, then Update, then LateUpdate.</summary>
        public static void Frame(float deltaTime)
        {
            Time.deltaTime = deltaTime;
            List<Behaviour> live = Objects.Where(o => o.activeInHierarchy)
                                          .SelectMany(o => o.Components.OfType<Behaviour>())
                                          .Where(b => b.enabled && AwokenComponents.Contains(b)).ToList();
            foreach (Behaviour behaviour in live.Where(b => !Started.Contains(b)))
            {
                Started.Add(behaviour);
                Call(behaviour, "Start");
            }
            foreach (Behaviour behaviour in live.Where(b => b.enabled)) Call(behaviour, "Update");
            foreach (Behaviour behaviour in live.Where(b => b.enabled)) Call(behaviour, "LateUpdate");
        }

        /// <summary>Destroys every object (OnDisable, OnDestroy), as leaving play mode does.</summary>
        public static void DestroyAll()
        {
            foreach (GameObject gameObject in Objects.Where(o => o.transform.parent == null).ToArray()) gameObject.DestroyAll();
            Objects.Clear();
            AwokenComponents.Clear();
            Started.Clear();
        }
    }
}
