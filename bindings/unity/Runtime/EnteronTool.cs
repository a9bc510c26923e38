// SPDX-License-Identifier: Apache-2.0
// A surgical tool of an EnteronScene, driven by a Transform or by a haptic device, with the
// force and stiffness it feels. Its tip is at the pose's position and its shaft runs along
// the pose's up (+y) in Unity (local +z in Enteron: EnteronSpace).
//   Transform: every frame the main thread samples the target's pose in the scene's frame;
//              before every step the stepping thread plays those samples back a frame
//              behind, interpolated (PoseInterpolator), so the tool moves smoothly at 1 kHz.
//   Device:    the device's own thread (its servo loop at 1 kHz and more) calls
//              PostDevicePose and ReadFeedback; both are wait-free and allocate nothing.
using System;
using System.Diagnostics;
using UnityEngine;

namespace Enteron.Unity
{
    /// <summary>A tool of an <see cref="EnteronScene"/> (docs: Documentation~/enteron.md).</summary>
    public sealed class EnteronTool : MonoBehaviour, IEnteronStepListener
    {
        /// <summary>What moves the tool.</summary>
        public enum PoseSource
        {
            /// <summary>the target Transform, sampled every frame</summary>
            Transform,
            /// <summary>a haptic device's thread, through PostDevicePose</summary>
            Device,
        }

        [Tooltip("The scene (default: the EnteronScene on this object or a parent).")]
        public EnteronScene scene;

        [Tooltip("The scene's tool with this id (a JSON scene's tools are 0, 1, ...); -1: add one with the settings below.")]
        public int toolId = -1;

        [Tooltip("New tool: shaft radius, m.")]
        public float radius = 0.005f;

        [Tooltip("New tool: shaft length from the tip, m.")]
        public float length = 0.3f;

        [Tooltip("New tool: the bound of its force, N.")]
        public float maxForce = 5f;

        [Tooltip("New tool: proxy (never passes through the bowel) or direct.")]
        public ToolMode mode = ToolMode.Proxy;

        [Tooltip("What moves the tool.")]
        public PoseSource poseSource = PoseSource.Transform;

        [Tooltip("Transform source: the Transform to follow (default: this one).")]
        public Transform target;

        [Tooltip("Transform source: how far behind the frames the tool plays their motion, s (about one frame).")]
        public float interpolationDelay = 1f / 60f;

        /// <summary>The tool (null until the stepping thread has added it).</summary>
        public Tool Tool
        {
            get { return _tool; }
        }

        /// <summary>The force of the bowel on the tool, N, in the scene's frame (Unity axes); read every frame.</summary>
        public Vector3 Force { get; private set; }

        /// <summary>The torque about the tip, N m, in the scene's frame; read every frame.</summary>
        public Vector3 Torque { get; private set; }

        /// <summary>dForce/dTip, N/m, in the scene's frame (upper-left 3 x 3; MultiplyVector); read every frame.</summary>
        public Matrix4x4 Stiffness { get; private set; }

        /// <summary>Whether a grasp holds; read every frame.</summary>
        public bool IsGrasping { get; private set; }

        /// <summary>The last feedback read in Update, as the C API gives it (Enteron's frame).</summary>
        public ToolFeedback Feedback { get; private set; }

        private volatile Tool _tool;
        private bool _added;
        private readonly PoseInterpolator _poses = new PoseInterpolator();

        /// <summary>Grasps at the start of the next step (any thread).</summary>
        public void Grasp()
        {
            if (_tool != null) _tool.Grasp();
        }

        /// <summary>Releases at the start of the next step (any thread).</summary>
        public void Release()
        {
            if (_tool != null) _tool.Release();
        }

        /// <summary>
        /// Device source: where the device puts the tip, in the scene's frame (Unity axes, m),
        /// and its rotation (shaft along up). Any thread, wait-free, allocates nothing.
        /// </summary>
        public void PostDevicePose(Vector3 position, Quaternion rotation)
        {
            Tool tool = _tool;
            if (tool != null) tool.SetPose(EnteronSpace.ToEnteron(position), EnteronSpace.ToEnteron(rotation));
        }

        /// <summary>What the tool felt in the last published step (Enteron's frame: EnteronSpace converts). Any thread.</summary>
        public ToolFeedback ReadFeedback()
        {
            Tool tool = _tool;
            return tool == null ? new ToolFeedback() : tool.ReadFeedback();
        }

        private void Start()
        {
            if (scene == null) scene = GetComponentInParent<EnteronScene>();
            if (target == null) target = transform;
            if (scene == null || scene.Scene == null)
            {
                UnityEngine.Debug.LogError("EnteronTool " + name + ": no loaded EnteronScene on this object or a parent", this);
                enabled = false;
                return;
            }
            if (toolId >= 0)
            {
                _tool = scene.Scene.GetTool(toolId);
            }
            else
            {
                ToolDesc desc = ToolDesc.Default();
                desc.radius_m = radius;
                desc.length_m = length;
                desc.max_force_N = maxForce;
                desc.mode = mode;
                Vector3 position;
                Quaternion rotation;
                TargetPose(out position, out rotation);
                desc.position_m = EnteronSpace.ToEnteron(position);
                desc.orientation_wxyz = EnteronSpace.ToEnteron(rotation);
                _added = true;
                scene.Drive(s => _tool = s.AddTool(desc));  // a driving call: on the stepping thread
            }
            scene.AddListener(this);
        }

        private void Update()
        {
            if (poseSource == PoseSource.Transform && target != null)
            {
                Vector3 position;
                Quaternion rotation;
                TargetPose(out position, out rotation);
                _poses.Write(Stopwatch.GetTimestamp(), EnteronSpace.ToEnteron(position), EnteronSpace.ToEnteron(rotation));
            }
            Tool tool = _tool;
            if (tool == null) return;
            ToolFeedback feedback = tool.ReadFeedback();
            Feedback = feedback;
            Force = EnteronSpace.ToUnity(feedback.force_N);
            Torque = -EnteronSpace.ToUnity(feedback.torque_Nm);  // a mirror turns a torque (an axial vector) round
            Stiffness = EnteronSpace.ToUnity(feedback.stiffness_N_per_m);
            IsGrasping = feedback.IsGrasping;
        }

        /// <summary>The stepping thread, before each step: the Transform's pose a frame ago, interpolated.</summary>
        public void BeforeStep(Scene stepping)
        {
            Tool tool = _tool;
            if (tool == null || poseSource != PoseSource.Transform) return;
            long delay = (long)(interpolationDelay * Stopwatch.Frequency);
            Vec3 position;
            Quat orientation;
            if (_poses.Read(Stopwatch.GetTimestamp() - delay, out position, out orientation))
                tool.SetPose(position, orientation);
        }

        private void OnDestroy()
        {
            if (scene == null) return;
            scene.RemoveListener(this);
            Tool tool = _tool;
            if (_added && tool != null && scene.Scene != null && !scene.Scene.IsDisposed)
                scene.Drive(s => tool.Remove());
            _tool = null;
        }

        /// <summary>The target's pose in the scene's frame (main thread: Transforms live there).</summary>
        private void TargetPose(out Vector3 position, out Quaternion rotation)
        {
            Transform frame = scene.transform;
            position = frame.InverseTransformPoint(target.position);
            rotation = Quaternion.Inverse(frame.rotation) * target.rotation;
        }
    }
}
