// SPDX-License-Identifier: Apache-2.0
// An Enteron scene in a Unity scene. It loads the description in Awake and steps it:
//   PhysicsThread  a thread of its own at 1 kHz (the default), from Start: each tick runs the step
//                  listeners (tools posting their poses), the queued driving calls, then
//                  one step of Timestep seconds, on an absolute Stopwatch schedule (sleeping
//                  when more than 2 ms ahead, yielding otherwise); an overloaded machine
//                  slows the simulation down instead of stepping in bursts.
//   EveryFrame     Unity's main thread, in Update: the frame's Time.deltaTime in steps of
//                  Timestep, at most MaxStepsPerFrame of them.
//   Manual         whoever calls Advance or StepOnce (a haptic device's servo callback):
//                  that thread is the driving thread.
// The skin renderers and the tools' readings never wait for the step (they read the
// published snapshots); the driving calls go through Drive or a step listener, so that they
// run on the stepping thread between steps, as the C API wants them.
using System;
using System.Collections.Concurrent;
using System.Diagnostics;
using System.IO;
using System.Threading;
using UnityEngine;

namespace Enteron.Unity
{
    /// <summary>An Enteron scene stepped at 1 kHz (docs: Documentation~/enteron.md).</summary>
    [DisallowMultipleComponent]
    public sealed class EnteronScene : MonoBehaviour
    {
        /// <summary>Who steps the scene.</summary>
        public enum Stepping
        {
            /// <summary>a thread of this component at 1 / Timestep Hz</summary>
            PhysicsThread,
            /// <summary>Unity's main thread, the frame's time in steps of Timestep</summary>
            EveryFrame,
            /// <summary>the caller, through Advance or StepOnce</summary>
            Manual,
        }

        [Tooltip("A JSON scene file (docs/scene-json.md): absolute, or relative to Application.streamingAssetsPath. " +
                 "Its organ meshes are found next to it.")]
        public string sceneFile = "";

        [Tooltip("Or the JSON text of the scene (used when sceneFile is empty).")]
        public TextAsset sceneJson;

        [Tooltip("Who steps the scene.")]
        public Stepping stepping = Stepping.PhysicsThread;

        [Tooltip("Simulated seconds per step (and the physics thread's period).")]
        public double timestep = 0.001;

        [Tooltip("EveryFrame: the most steps one frame makes; a slower frame slows the simulation down.")]
        public int maxStepsPerFrame = 50;

        /// <summary>The scene (null before Awake, after OnDestroy, or if it could not be loaded).</summary>
        public Scene Scene { get; private set; }

        /// <summary>Steps made so far.</summary>
        public long Steps
        {
            get { return Interlocked.Read(ref _steps); }
        }

        /// <summary>Times the physics thread fell more than ten periods behind and restarted its schedule.</summary>
        public long LateRestarts
        {
            get { return Interlocked.Read(ref _lateRestarts); }
        }

        /// <summary>Steps that failed (EnteronException, e.g. Unstable; the state stayed as it was).</summary>
        public long FailedSteps
        {
            get { return Interlocked.Read(ref _failedSteps); }
        }

        private IEnteronStepListener[] _listeners = new IEnteronStepListener[0];
        private readonly object _listenersLock = new object();
        private readonly ConcurrentQueue<Action<Scene>> _drives = new ConcurrentQueue<Action<Scene>>();
        private Thread _thread;
        private volatile bool _stop;
        private bool _started;
        private long _steps, _lateRestarts, _failedSteps, _errorsReported;
        private volatile string _lastError;
        private long _errors;
        private double _pending;  // EveryFrame and Manual: time not yet stepped

        /// <summary>
        /// Adds a listener called before every step on the stepping thread (a tool, a moving
        /// organ). Any thread; allocates (not on the physics thread).
        /// </summary>
        public void AddListener(IEnteronStepListener listener)
        {
            lock (_listenersLock)
            {
                var grown = new IEnteronStepListener[_listeners.Length + 1];
                Array.Copy(_listeners, grown, _listeners.Length);
                grown[_listeners.Length] = listener;
                _listeners = grown;  // the stepping thread reads the array it got, never a half-built one
            }
        }

        /// <summary>Removes a listener; from the next tick on it is not called.</summary>
        public void RemoveListener(IEnteronStepListener listener)
        {
            lock (_listenersLock)
            {
                int index = Array.IndexOf(_listeners, listener);
                if (index < 0) return;
                var shrunk = new IEnteronStepListener[_listeners.Length - 1];
                Array.Copy(_listeners, 0, shrunk, 0, index);
                Array.Copy(_listeners, index + 1, shrunk, index, shrunk.Length - index);
                _listeners = shrunk;
            }
        }

        /// <summary>
        /// Runs a driving call (AddTool, AddObstacle, Tool.Remove, SaveState, ...) on the
        /// stepping thread before the next step. Any thread. An exception it throws is
        /// logged on the main thread.
        /// </summary>
        public void Drive(Action<Scene> call)
        {
            if (call == null) throw new ArgumentNullException("call");
            _drives.Enqueue(call);
        }

        /// <summary>Manual and EveryFrame: steps the time given, in steps of timestep (the remainder carries over).</summary>
        public void Advance(double seconds)
        {
            if (stepping == Stepping.PhysicsThread)
                throw new InvalidOperationException("EnteronScene.Advance: the scene steps on its physics thread");
            _pending += seconds;
            int steps = 0;
            while (_pending >= timestep && steps < maxStepsPerFrame)
            {
                Tick();
                _pending -= timestep;
                ++steps;
            }
            if (steps == maxStepsPerFrame) _pending = 0;  // too slow: slow the simulation down, no catching up
        }

        /// <summary>Manual: one step of timestep seconds, now, on the calling thread (a device's servo loop).</summary>
        public void StepOnce()
        {
            if (stepping == Stepping.PhysicsThread)
                throw new InvalidOperationException("EnteronScene.StepOnce: the scene steps on its physics thread");
            Tick();
        }

        private void Awake()
        {
            try
            {
                Library.EnsureCompatible();
                if (!string.IsNullOrEmpty(sceneFile))
                    Scene = Scene.FromFile(Path.IsPathRooted(sceneFile)
                                               ? sceneFile
                                               : Path.Combine(Application.streamingAssetsPath, sceneFile));
                else if (sceneJson != null)
                    Scene = Scene.FromJson(sceneJson.text);
                else
                    UnityEngine.Debug.LogError("EnteronScene " + name + ": set sceneFile or sceneJson", this);
            }
            catch (Exception error)
            {
                UnityEngine.Debug.LogError("EnteronScene " + name + ": " + error.Message, this);
            }
            if (Scene == null) enabled = false;
        }

        // The physics thread starts in Start, after every Awake: what other components do
        // with the scene in their Awake (read its organ meshes, a driving call) happens before
        // it steps. Disabling the component pauses it.
        private void Start()
        {
            _started = true;
            StartThread();
        }

        private void OnEnable()
        {
            if (_started) StartThread();
        }

        private void OnDisable()
        {
            StopThread();
        }

        private void OnDestroy()
        {
            StopThread();
            if (Scene != null) Scene.Dispose();  // its skins keep the last published state
            Scene = null;
        }

        private void Update()
        {
            if (stepping == Stepping.EveryFrame && Scene != null) Advance(Time.deltaTime);
            long errors = Interlocked.Read(ref _errors);
            if (errors != _errorsReported)
            {
                UnityEngine.Debug.LogError(string.Format("EnteronScene {0}: {1} ({2} error(s) so far)", name, _lastError, errors),
                                           this);
                _errorsReported = errors;
            }
        }

        private void StartThread()
        {
            if (Scene == null || stepping != Stepping.PhysicsThread || _thread != null) return;
            _stop = false;
            _thread = new Thread(Run) { Name = "Enteron physics", IsBackground = true };
            _thread.Start();
        }

        private void StopThread()
        {
            if (_thread == null) return;
            _stop = true;
            _thread.Join();
            _thread = null;
        }

        private void Run()
        {
            long period = (long)(timestep * Stopwatch.Frequency);
            long twoMilliseconds = Stopwatch.Frequency / 500;
            long next = Stopwatch.GetTimestamp();
            while (!_stop)
            {
                if (!Tick()) return;
                next += period;
                long now = Stopwatch.GetTimestamp();
                if (now - next > 10 * period)
                {
                    next = now;
                    Interlocked.Increment(ref _lateRestarts);
                }
                while ((now = Stopwatch.GetTimestamp()) < next)
                {
                    if (next - now > twoMilliseconds) Thread.Sleep(1);
                    else Thread.Yield();
                }
            }
        }

        /// <summary>Listeners, queued driving calls, one step. False once the scene is gone.</summary>
        private bool Tick()
        {
            Scene scene = Scene;
            if (scene == null) return false;
            try
            {
                IEnteronStepListener[] listeners = _listeners;
                for (int i = 0; i < listeners.Length; ++i) listeners[i].BeforeStep(scene);
                Action<Scene> call;
                while (_drives.TryDequeue(out call)) call(scene);
                scene.Step(timestep);
                Interlocked.Increment(ref _steps);
            }
            catch (ObjectDisposedException)
            {
                return false;
            }
            catch (Exception error)
            {
                if (error is EnteronException && ((EnteronException)error).Function == "ent_scene_step")
                    Interlocked.Increment(ref _failedSteps);
                _lastError = error.Message;
                Interlocked.Increment(ref _errors);
            }
            return true;
        }
    }
}
