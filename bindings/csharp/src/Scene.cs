// SPDX-License-Identifier: Apache-2.0
using System;
using System.Text;

namespace Enteron
{
    /// <summary>
    /// A simulated intestine and its surroundings (ent_scene).
    /// <code>
    /// using (var scene = Scene.FromJson(json))
    /// {
    ///     for (int i = 0; i &lt; 1000; ++i) scene.Step(0.001);
    ///     var axis = new double[100 * 3];
    ///     scene.Axis(axis);
    /// }
    /// </code>
    /// Threads, as in C (include/enteron/enteron.h; bindings/csharp/README.md):
    /// - Driving calls, one at a time per scene: <see cref="Step"/>, AddObstacle, AddTool,
    ///   RemoveTool, SaveState, RestoreState and the changes between steps (SetObstaclePose,
    ///   ...). A driving call while another runs on another thread throws an
    ///   <see cref="EnteronException"/> with <see cref="Status.Busy"/> and changes nothing.
    /// - The tool commands (<see cref="Tool.SetPose"/>, Grasp, Release) and the queries
    ///   (Axis, GetStats, Tool.ReadFeedback, ...) are safe from any thread at any time and
    ///   never wait for the step.
    /// - <see cref="Dispose"/> may come from any thread at any time: a call in flight ends
    ///   first, and every later call throws ObjectDisposedException.
    /// Failures throw <see cref="EnteronException"/> with the library's message; the
    /// failed call changed nothing. The calls of a 1 kHz loop (Step, Tool.SetPose,
    /// Tool.Grasp, Tool.Release, Tool.ReadFeedback, Tool.Stiffness, Tool.GetWrench, the
    /// queries into caller arrays) allocate nothing on the managed heap.
    /// </summary>
    public sealed unsafe class Scene : IDisposable
    {
        /// <summary>No obstacle: the world (PinPoint, AttachMesentery, AttachClampedEnd).</summary>
        public const int NoObstacle = -1;

        private readonly SceneHandle _handle;
        private volatile bool _disposed;

        private Scene(SceneHandle handle)
        {
            _handle = handle;
        }

        /// <summary>
        /// The handle for a call; throws ObjectDisposedException once Dispose was called.
        /// The SafeHandle alone makes a call after its destroy impossible; this check also
        /// refuses new calls at once while others are in flight, so that the destroy is not
        /// put off for as long as two threads keep overlapping calls.
        /// </summary>
        internal SceneHandle Handle
        {
            get
            {
                if (_disposed) throw new ObjectDisposedException("Enteron.Scene", "the scene was disposed");
                return _handle;
            }
        }

        // ---- creation ---------------------------------------------------------------------

        /// <summary>
        /// A scene from a JSON description (docs/scene-json.md). A mesh obstacle's "file" is
        /// found relative to the process's current directory (<see cref="FromFile"/> finds
        /// it next to the scene file).
        /// </summary>
        /// <exception cref="EnteronException">Parse (not JSON), InvalidScene (a wrong key or value: the message names its path).</exception>
        public static Scene FromJson(string json, Callbacks callbacks = null)
        {
            Arguments.NotNull(json, "json");
            Library.EnsureCompatible();
            byte[] text = Encoding.UTF8.GetBytes(json);
            CallbackState state = CallbackState.Create(callbacks);
            SceneHandle handle;
            Status status;
            if (state == null)
            {
                status = NativeMethods.ent_scene_create_json(text, (UIntPtr)text.Length, out handle);
            }
            else
            {
                fixed (NativeCallbacks* native = &state.Native)
                    status = NativeMethods.ent_scene_create_json_with(text, (UIntPtr)text.Length, native, out handle);
            }
            return Adopt(status, "ent_scene_create_json", handle, state);
        }

        /// <summary>
        /// A scene from a JSON file; its mesh obstacles' files are found relative to the
        /// file's directory. Reading meshes and building their distance fields takes time:
        /// not on a real-time thread.
        /// </summary>
        public static Scene FromFile(string path, Callbacks callbacks = null)
        {
            Arguments.NotNull(path, "path");
            Library.EnsureCompatible();
            byte[] file = Utf8.NulTerminated(path);
            CallbackState state = CallbackState.Create(callbacks);
            SceneHandle handle;
            Status status;
            if (state == null)
            {
                status = NativeMethods.ent_scene_create_json_file(file, null, out handle);
            }
            else
            {
                fixed (NativeCallbacks* native = &state.Native)
                    status = NativeMethods.ent_scene_create_json_file(file, native, out handle);
            }
            return Adopt(status, "ent_scene_create_json_file", handle, state);
        }

        /// <summary>
        /// A scene from a C description (start from <see cref="SceneDesc.Default"/>).
        /// </summary>
        /// <param name="desc">the description; not retained.</param>
        /// <param name="shapePointsXyz">for <see cref="Shape.Points"/>: the control points, x y z each, m
        /// (sets desc.shape to Points and desc.control_points to their number); else null.</param>
        /// <param name="pinnedPoints">control point indices to hold (the Pinned effect), or null.</param>
        /// <param name="callbacks">log and allocator hooks, or null.</param>
        public static Scene FromDescription(SceneDesc desc, double[] shapePointsXyz = null, uint[] pinnedPoints = null,
                                            Callbacks callbacks = null)
        {
            return FromDescriptionAndProfiles(desc, null, shapePointsXyz, pinnedPoints, callbacks);
        }

        /// <summary>
        /// A scene from a C description with properties along the length (see <see cref="Profiles"/>;
        /// null: none); the other parameters as in <see cref="FromDescription"/>.
        /// </summary>
        public static Scene FromDescriptionAndProfiles(SceneDesc desc, Profiles profiles, double[] shapePointsXyz = null,
                                            uint[] pinnedPoints = null, Callbacks callbacks = null)
        {
            Library.EnsureCompatible();
            profiles = profiles ?? new Profiles();
            Arguments.Multiple(profiles.Radius?.Length ?? 0, 2, "profiles.Radius", "pair");
            Arguments.Multiple(profiles.LinearDensity?.Length ?? 0, 2, "profiles.LinearDensity", "pair");
            Arguments.Multiple(profiles.StretchStiffness?.Length ?? 0, 2, "profiles.StretchStiffness", "pair");
            Arguments.Multiple(profiles.BendStiffness?.Length ?? 0, 2, "profiles.BendStiffness", "pair");
            if (shapePointsXyz != null)
            {
                Arguments.Multiple(shapePointsXyz.Length, 3, "shapePointsXyz", "point");
                desc.shape = Shape.Points;
                desc.control_points = (uint)(shapePointsXyz.Length / 3);
            }
            CallbackState state = CallbackState.Create(callbacks);
            SceneHandle handle;
            Status status;
            fixed (double* points = shapePointsXyz)
            fixed (uint* pinned = pinnedPoints)
            fixed (double* radius = profiles.Radius)
            fixed (double* density = profiles.LinearDensity)
            fixed (double* stretch = profiles.StretchStiffness)
            fixed (double* bend = profiles.BendStiffness)
            {
                desc.radius_profile_m = (IntPtr)radius;
                desc.radius_profile_count = (uint)((profiles.Radius?.Length ?? 0) / 2);
                desc.linear_density_profile_kg_per_m = (IntPtr)density;
                desc.linear_density_profile_count = (uint)((profiles.LinearDensity?.Length ?? 0) / 2);
                desc.stretch_stiffness_profile_N = (IntPtr)stretch;
                desc.stretch_stiffness_profile_count = (uint)((profiles.StretchStiffness?.Length ?? 0) / 2);
                desc.bend_stiffness_profile_N_m2 = (IntPtr)bend;
                desc.bend_stiffness_profile_count = (uint)((profiles.BendStiffness?.Length ?? 0) / 2);
                desc.shape_points_xyz_m = (IntPtr)points;
                desc.pinned_points = (IntPtr)pinned;
                desc.pinned_point_count = pinnedPoints == null ? 0u : (uint)pinnedPoints.Length;
                if (state == null)
                {
                    desc.callbacks = IntPtr.Zero;
                    status = NativeMethods.ent_scene_create(ref desc, out handle);
                }
                else
                {
                    fixed (NativeCallbacks* native = &state.Native)
                    {
                        desc.callbacks = (IntPtr)native;
                        status = NativeMethods.ent_scene_create(ref desc, out handle);
                    }
                }
            }
            return Adopt(status, "ent_scene_create", handle, state);
        }

        private static Scene Adopt(Status status, string function, SceneHandle handle, CallbackState callbacks)
        {
            if (status != Status.Ok)
            {
                string message = Library.LastError;  // first, before anything else can fail on this thread
                handle.Dispose();  // holds no scene: nothing to destroy, no finalizer to run
                if (callbacks != null) callbacks.Release();
                throw new EnteronException(status, function, message);
            }
            handle.Callbacks = callbacks;
            return new Scene(handle);
        }

        // ---- lifetime ---------------------------------------------------------------------

        /// <summary>
        /// Destroys the scene (ent_scene_destroy) once no call on it is running; any thread,
        /// any time, more than once. Its skins keep working on the last published state.
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

        // ---- driving ----------------------------------------------------------------------

        /// <summary>
        /// Advances by <paramref name="dtSeconds"/> (ent_scene_step), taking the tools'
        /// commands first. A driving call; allocates nothing.
        /// </summary>
        /// <exception cref="EnteronException">InvalidArgument (dt), Busy, Unstable (the state is as before the call).</exception>
        public void Step(double dtSeconds)
        {
            EnteronException.Check(NativeMethods.ent_scene_step(Handle, dtSeconds), "ent_scene_step");
        }

        /// <summary>
        /// Sets gravity from the next step on, m/s^2 (ent_scene_set_gravity): a table tilt. A
        /// driving call, between steps.
        /// </summary>
        public void SetGravity(Vec3 gravity_m_per_s2)
        {
            EnteronException.Check(NativeMethods.ent_scene_set_gravity(Handle, &gravity_m_per_s2),
                                   "ent_scene_set_gravity");
        }

        /// <summary>Holds a control point where it is, in the world or on an obstacle's frame (ent_scene_pin_point). Driving.</summary>
        public void PinPoint(int controlPoint, int obstacle = NoObstacle)
        {
            EnteronException.Check(NativeMethods.ent_scene_pin_point(Handle, Arguments.Index(controlPoint, "controlPoint"),
                                                                     obstacle), "ent_scene_pin_point");
        }

        /// <summary>Lets a pinned control point go (ent_scene_unpin_point). Driving.</summary>
        public void UnpinPoint(int controlPoint)
        {
            EnteronException.Check(NativeMethods.ent_scene_unpin_point(Handle, Arguments.Index(controlPoint, "controlPoint")),
                                   "ent_scene_unpin_point");
        }

        /// <summary>Attaches the mesentery's root to an obstacle's frame, or leaves it in the world (ent_scene_attach_mesentery). Driving.</summary>
        public void AttachMesentery(int obstacle = NoObstacle)
        {
            EnteronException.Check(NativeMethods.ent_scene_attach_mesentery(Handle, obstacle), "ent_scene_attach_mesentery");
        }

        /// <summary>Attaches clamped ends to an obstacle's frame (ent_scene_attach_clamped_end). Driving.</summary>
        public void AttachClampedEnd(PinnedEnds ends, int obstacle = NoObstacle)
        {
            EnteronException.Check(NativeMethods.ent_scene_attach_clamped_end(Handle, ends, obstacle),
                                   "ent_scene_attach_clamped_end");
        }

        // ---- obstacles --------------------------------------------------------------------

        /// <summary>
        /// Adds a rigid obstacle (ent_scene_add_obstacle) and returns its index. A mesh
        /// (<see cref="ObstacleKind.Mesh"/>) takes its vertices (x y z each, m, in its frame)
        /// and triangles (3 vertex indices each, counter-clockwise seen from the bowel's
        /// side); the library copies them. Allocates: a driving call, between steps.
        /// </summary>
        public int AddObstacle(ObstacleDesc desc, double[] meshVerticesXyz = null, uint[] meshTriangles = null)
        {
            if (meshVerticesXyz != null) Arguments.Multiple(meshVerticesXyz.Length, 3, "meshVerticesXyz", "vertex");
            if (meshTriangles != null) Arguments.Multiple(meshTriangles.Length, 3, "meshTriangles", "triangle");
            int obstacle;
            fixed (double* vertices = meshVerticesXyz)
            fixed (uint* triangles = meshTriangles)
            {
                desc.mesh_vertices_xyz_m = (IntPtr)vertices;
                desc.mesh_vertex_count = meshVerticesXyz == null ? 0u : (uint)(meshVerticesXyz.Length / 3);
                desc.mesh_triangles = (IntPtr)triangles;
                desc.mesh_triangle_count = meshTriangles == null ? 0u : (uint)(meshTriangles.Length / 3);
                EnteronException.Check(NativeMethods.ent_scene_add_obstacle(Handle, ref desc, out obstacle),
                                       "ent_scene_add_obstacle");
            }
            return obstacle;
        }

        /// <summary>Removes an obstacle from the next step on (ent_scene_remove_obstacle). Driving.</summary>
        public void RemoveObstacle(int obstacle)
        {
            EnteronException.Check(NativeMethods.ent_scene_remove_obstacle(Handle, obstacle), "ent_scene_remove_obstacle");
        }

        /// <summary>
        /// Moves an obstacle's frame to this pose by the end of the next step
        /// (ent_obstacle_set_pose). Driving, between steps; allocates nothing.
        /// </summary>
        public void SetObstaclePose(int obstacle, Vec3 position_m, Quat orientation)
        {
            EnteronException.Check(NativeMethods.ent_obstacle_set_pose(Handle, obstacle, &position_m, &orientation),
                                   "ent_obstacle_set_pose");
        }

        /// <summary>The velocity the obstacle's contacts see in the next step: m/s and rad/s (ent_obstacle_set_velocity). Driving.</summary>
        public void SetObstacleVelocity(int obstacle, Vec3 linear_m_per_s, Vec3 angular_rad_per_s)
        {
            EnteronException.Check(NativeMethods.ent_obstacle_set_velocity(Handle, obstacle, &linear_m_per_s,
                                                                           &angular_rad_per_s), "ent_obstacle_set_velocity");
        }

        /// <summary>An obstacle's Coulomb friction coefficient, >= 0; negative: the scene's (ent_obstacle_set_friction). Driving.</summary>
        public void SetObstacleFriction(int obstacle, double friction)
        {
            EnteronException.Check(NativeMethods.ent_obstacle_set_friction(Handle, obstacle, friction),
                                   "ent_obstacle_set_friction");
        }

        /// <summary>Obstacles in the last published state, removed ones not counted (ent_scene_obstacle_count). Any thread.</summary>
        public int ObstacleCount
        {
            get
            {
                uint count;
                EnteronException.Check(NativeMethods.ent_scene_obstacle_count(Handle, out count), "ent_scene_obstacle_count");
                return (int)count;
            }
        }

        /// <summary>Where an obstacle's frame rests in the last published state (ent_obstacle_pose). Any thread.</summary>
        public void GetObstaclePose(int obstacle, out Vec3 position_m, out Quat orientation)
        {
            Vec3 position;
            Quat rotation;
            EnteronException.Check(NativeMethods.ent_obstacle_pose(Handle, obstacle, &position, &rotation),
                                   "ent_obstacle_pose");
            position_m = position;
            orientation = rotation;
        }

        /// <summary>A mesh obstacle's vertex and triangle counts (ent_obstacle_mesh). Driving, between steps.</summary>
        public void GetObstacleMeshCounts(int obstacle, out int vertices, out int triangles)
        {
            uint vertexCount, triangleCount;
            EnteronException.Check(NativeMethods.ent_obstacle_mesh(Handle, obstacle, 0, null, out vertexCount, 0, null,
                                                                   out triangleCount), "ent_obstacle_mesh");
            vertices = (int)vertexCount;
            triangles = (int)triangleCount;
        }

        /// <summary>
        /// Copies a mesh obstacle's vertices (x y z each, m, in its frame) and triangles (3
        /// indices each) into the caller's arrays; either may be null (ent_obstacle_mesh).
        /// Driving, between steps.
        /// </summary>
        /// <exception cref="EnteronException">BufferTooSmall (size them with GetObstacleMeshCounts), NotFound, InvalidArgument (not a mesh).</exception>
        public void CopyObstacleMesh(int obstacle, double[] verticesXyz, uint[] triangles)
        {
            uint vertexCount, triangleCount;
            fixed (double* vertices = verticesXyz)
            fixed (uint* indices = triangles)
            {
                EnteronException.Check(NativeMethods.ent_obstacle_mesh(
                    Handle, obstacle, verticesXyz == null ? 0u : (uint)(verticesXyz.Length / 3), vertices, out vertexCount,
                    triangles == null ? 0u : (uint)(triangles.Length / 3), indices, out triangleCount), "ent_obstacle_mesh");
            }
            // An empty array reached C as NULL, which asks for the count only.
            if (verticesXyz != null) Arguments.Fits((int)vertexCount, 3, verticesXyz.Length, "verticesXyz");
            if (triangles != null) Arguments.Fits((int)triangleCount, 3, triangles.Length, "triangles");
        }

        // ---- tools ----------------------------------------------------------------------------

        /// <summary>
        /// Adds a surgical tool at the desc's pose (ent_tool_add) and returns it. Allocates: a
        /// driving call, between steps.
        /// </summary>
        public Tool AddTool(ToolDesc desc)
        {
            int id;
            EnteronException.Check(NativeMethods.ent_tool_add(Handle, ref desc, out id), "ent_tool_add");
            return new Tool(this, id);
        }

        /// <summary>
        /// The tool with this id (0, 1, ...; a JSON description's tools come first). Keep the
        /// object: each call makes a new one.
        /// </summary>
        /// <exception cref="EnteronException">NotFound (no such tool, or removed).</exception>
        public Tool GetTool(int id)
        {
            int grasping;
            EnteronException.Check(NativeMethods.ent_tool_state(Handle, id, out grasping), "ent_tool_state");
            return new Tool(this, id);
        }

        /// <summary>Tools added and not removed (ent_scene_tool_count). Any thread.</summary>
        public int ToolCount
        {
            get
            {
                int count;
                EnteronException.Check(NativeMethods.ent_scene_tool_count(Handle, out count), "ent_scene_tool_count");
                return count;
            }
        }

        // ---- queries of the last published state (any thread, never wait) ---------------------

        /// <summary>
        /// Copies <paramref name="count"/> points evenly spaced along the axis, x y z each, m,
        /// into <paramref name="pointsXyz"/> (ent_scene_axis). Allocates nothing.
        /// </summary>
        public void Axis(double[] pointsXyz, int count)
        {
            Arguments.NotNull(pointsXyz, "pointsXyz");
            Arguments.Fits(count, 3, pointsXyz.Length, "pointsXyz");
            fixed (double* points = pointsXyz) Axis(points, count);
        }

        /// <summary>As <see cref="Axis(double[], int)"/> with as many points as the array holds (Length / 3).</summary>
        public void Axis(double[] pointsXyz)
        {
            Arguments.NotNull(pointsXyz, "pointsXyz");
            Axis(pointsXyz, pointsXyz.Length / 3);
        }

        /// <summary>As <see cref="Axis(double[], int)"/> into native memory that holds 3 count doubles.</summary>
        public void Axis(double* pointsXyz, int count)
        {
            if (count < 0) throw new ArgumentOutOfRangeException("count", count, "must be >= 0");
            EnteronException.Check(NativeMethods.ent_scene_axis(Handle, (uint)count, pointsXyz), "ent_scene_axis");
        }

        /// <summary>The number of intestines (tubes), each its own axis (ent_scene_intestine_count).</summary>
        public int IntestineCount
        {
            get
            {
                int count;
                EnteronException.Check(NativeMethods.ent_scene_intestine_count(Handle, out count),
                                       "ent_scene_intestine_count");
                return count;
            }
        }

        /// <summary>
        /// Copies <paramref name="count"/> points evenly spaced along intestine
        /// <paramref name="intestine"/>'s axis, x y z each, m, into <paramref name="pointsXyz"/>
        /// (ent_scene_intestine_axis; intestine 0 is <see cref="Axis(double[], int)"/>'s). Allocates nothing.
        /// </summary>
        public void IntestineAxis(int intestine, double[] pointsXyz, int count)
        {
            Arguments.NotNull(pointsXyz, "pointsXyz");
            Arguments.Fits(count, 3, pointsXyz.Length, "pointsXyz");
            if (count < 0) throw new ArgumentOutOfRangeException("count", count, "must be >= 0");
            fixed (double* points = pointsXyz)
                EnteronException.Check(NativeMethods.ent_scene_intestine_axis(Handle, intestine, (UIntPtr)count, points),
                                       "ent_scene_intestine_axis");
        }

        /// <summary>The number of control points (ent_scene_control_points with no buffer).</summary>
        public int ControlPointCount
        {
            get
            {
                uint count;
                EnteronException.Check(NativeMethods.ent_scene_control_points(Handle, 0, null, out count),
                                       "ent_scene_control_points");
                return (int)count;
            }
        }

        /// <summary>
        /// Copies the control points, x y z each, m, into the array (its capacity: Length / 3
        /// points) and returns their number (ent_scene_control_points). Allocates nothing.
        /// </summary>
        /// <exception cref="EnteronException">BufferTooSmall.</exception>
        public int ControlPoints(double[] pointsXyz)
        {
            Arguments.NotNull(pointsXyz, "pointsXyz");
            int count;
            fixed (double* points = pointsXyz) count = ControlPoints(points, pointsXyz.Length / 3);
            Arguments.Fits(count, 3, pointsXyz.Length, "pointsXyz");  // an empty array asked for the count only
            return count;
        }

        /// <summary>As <see cref="ControlPoints(double[])"/> into native memory of capacityPoints x 3 doubles.</summary>
        public int ControlPoints(double* pointsXyz, int capacityPoints)
        {
            uint count;
            EnteronException.Check(NativeMethods.ent_scene_control_points(Handle, Arguments.Index(capacityPoints, "capacityPoints"),
                                                                          pointsXyz, out count), "ent_scene_control_points");
            return (int)count;
        }

        /// <summary>Counters and energies of the last published state (ent_scene_stats).</summary>
        public Stats GetStats()
        {
            var stats = new Stats();
            stats.struct_size = StructSize<Stats>.Value;
            EnteronException.Check(NativeMethods.ent_scene_stats(Handle, ref stats), "ent_scene_stats");
            return stats;
        }

        /// <summary>
        /// The description the scene was made from (ent_scene_read_desc), without its arrays
        /// (shape points and pinned points read back as none): a JSON scene's too.
        /// </summary>
        public SceneDesc ReadDescription()
        {
            SceneDesc desc = SceneDesc.Default();
            EnteronException.Check(NativeMethods.ent_scene_read_desc(Handle, ref desc), "ent_scene_read_desc");
            return desc;
        }

        /// <summary>What one effect cost so far (ent_scene_effect_stats).</summary>
        public EffectStats GetEffectStats(Effect effect)
        {
            var stats = new EffectStats();
            stats.struct_size = StructSize<EffectStats>.Value;
            EnteronException.Check(NativeMethods.ent_scene_effect_stats(Handle, effect, ref stats), "ent_scene_effect_stats");
            return stats;
        }

        // ---- contacts ----------------------------------------------------------------------------

        /// <summary>The bowel's contacts and stretch in the last published step (ent_scene_contact_summary).</summary>
        public ContactSummary GetContactSummary()
        {
            var summary = new ContactSummary();
            summary.struct_size = StructSize<ContactSummary>.Value;
            EnteronException.Check(NativeMethods.ent_scene_contact_summary(Handle, ref summary),
                                   "ent_scene_contact_summary");
            return summary;
        }

        /// <summary>
        /// Copies the contacts of the last published step into the array (the tools' first,
        /// then the obstacles', then the self-contacts') and returns their number
        /// (ent_scene_contacts). Size it once with GetContactSummary().capacity + 1.
        /// Allocates nothing.
        /// </summary>
        /// <exception cref="EnteronException">BufferTooSmall.</exception>
        public int ReadContacts(Contact[] contacts)
        {
            Arguments.NotNull(contacts, "contacts");
            if (contacts.Length == 0) throw new ArgumentException("contacts must hold at least one element", "contacts");
            uint count;
            fixed (Contact* first = contacts)
            {
                first->struct_size = StructSize<Contact>.Value;
                EnteronException.Check(NativeMethods.ent_scene_contacts(Handle, (uint)contacts.Length, first, out count),
                                       "ent_scene_contacts");
            }
            return (int)count;
        }

        // ---- save and restore (driving calls) ------------------------------------------------------

        /// <summary>The bytes the state needs now (ent_scene_save_state with no buffer); it varies with the contacts.</summary>
        public int SaveStateSize()
        {
            UIntPtr size;
            EnteronException.Check(NativeMethods.ent_scene_save_state(Handle, null, UIntPtr.Zero, out size),
                                   "ent_scene_save_state");
            return checked((int)size.ToUInt64());
        }

        /// <summary>
        /// Saves the whole state into the buffer and returns its length (ent_scene_save_state;
        /// docs/scoring-and-state.md). A scene restored from it continues bit for bit.
        /// </summary>
        /// <exception cref="EnteronException">BufferTooSmall (the state needs more room: see SaveStateSize), Busy.</exception>
        public int SaveState(byte[] buffer)
        {
            Arguments.NotNull(buffer, "buffer");
            if (buffer.Length == 0) throw new ArgumentException("buffer must not be empty (see SaveStateSize)", "buffer");
            UIntPtr size;
            fixed (byte* bytes = buffer)
                EnteronException.Check(NativeMethods.ent_scene_save_state(Handle, bytes, (UIntPtr)buffer.Length, out size),
                                       "ent_scene_save_state");
            return (int)size.ToUInt64();
        }

        /// <summary>The whole state as a new array (see <see cref="SaveState(byte[])"/>).</summary>
        public byte[] SaveState()
        {
            for (;;)
            {
                var buffer = new byte[SaveStateSize()];
                UIntPtr size;
                Status status;
                fixed (byte* bytes = buffer)
                    status = NativeMethods.ent_scene_save_state(Handle, bytes, (UIntPtr)buffer.Length, out size);
                if (status == Status.BufferTooSmall) continue;  // a step on another thread listed more contacts
                EnteronException.Check(status, "ent_scene_save_state");
                if ((int)size.ToUInt64() == buffer.Length) return buffer;
                var exact = new byte[(int)size.ToUInt64()];
                Buffer.BlockCopy(buffer, 0, exact, 0, exact.Length);
                return exact;
            }
        }

        /// <summary>
        /// Restores a state saved by SaveState from this scene or one made from the same
        /// description (ent_scene_restore_state). A damaged or foreign state changes nothing
        /// and throws with the library's message.
        /// </summary>
        public void RestoreState(byte[] state, int length)
        {
            Arguments.NotNull(state, "state");
            if (length < 0 || length > state.Length)
                throw new ArgumentOutOfRangeException("length", length, "must be within the array (0 to " + state.Length + ")");
            fixed (byte* bytes = state)
                EnteronException.Check(NativeMethods.ent_scene_restore_state(Handle, bytes, (UIntPtr)length),
                                       "ent_scene_restore_state");
        }

        /// <summary>As <see cref="RestoreState(byte[], int)"/> with the whole array.</summary>
        public void RestoreState(byte[] state)
        {
            Arguments.NotNull(state, "state");
            RestoreState(state, state.Length);
        }
    }
}
