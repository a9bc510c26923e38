// SPDX-License-Identifier: Apache-2.0
// Every function of include/enteron/enteron.h, declared once, in the header's order. The
// public classes (Scene, Tool, Skin, Library, the descriptions) are the only callers.
//
// Adding a C function is one line here, one wrapper where it belongs and one row in
// bindings/csharp/README.md's table (the test DocTests checks all three against the
// functions the built library exports).
//
// Conventions:
// - Handles are SafeHandles (SceneHandle, SkinHandle, ExposureHandle): the marshaller adds
//   a reference for the duration of each call, so a Dispose on another thread waits for the
//   call to return before the C destroy runs, and a call after Dispose throws
//   ObjectDisposedException.
// - Arrays of the C signatures (double[3], double[4], double[9]) are pointers to the
//   blittable Vec3, Quat and Matrix3; output structs are passed by ref (pinned, not
//   copied). Nothing here allocates on the managed heap except the handle objects that
//   the create functions return.
// - Strings come back as IntPtr (UTF-8, owned by the library; Utf8.FromNative decodes).
using System;
using System.Runtime.InteropServices;
using System.Security;

namespace Enteron
{
    [SuppressUnmanagedCodeSecurity]
    internal static unsafe class NativeMethods
    {
        // "enteron": libenteron.so on Linux (Mono maps it to libenteron.so.0 through
        // Enteron.dll.config), enteron.dll on Windows, libenteron.dylib on macOS; Unity finds
        // it among the package's plugins (bindings/unity/Documentation~/enteron.md).
        internal const string Library = "enteron";
        private const CallingConvention Cdecl = CallingConvention.Cdecl;

        // ---- version, status, errors ----------------------------------------------------
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern uint ent_version();

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr ent_status_string(Status status);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr ent_last_error();

        // ---- callbacks and descriptions ---------------------------------------------------
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_callbacks_init(ref NativeCallbacks callbacks, uint structSize);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_desc_init(ref SceneDesc desc, uint structSize);

        // ---- scenes ------------------------------------------------------------------------
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_create(ref SceneDesc desc, out SceneHandle scene);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_create_json(byte[] json, UIntPtr length, out SceneHandle scene);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_create_json_with(byte[] json, UIntPtr length,
                                                                 NativeCallbacks* callbacks, out SceneHandle scene);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_create_json_file(byte[] path, NativeCallbacks* callbacks,
                                                                 out SceneHandle scene);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern void ent_scene_destroy(IntPtr scene);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_step(SceneHandle scene, double dtSeconds);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_axis(SceneHandle scene, uint count, double* pointsXyz);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_control_points(SceneHandle scene, uint capacity, double* pointsXyz,
                                                               out uint count);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_intestine_count(SceneHandle scene, out int count);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_intestine_axis(SceneHandle scene, int intestine, UIntPtr count,
                                                               double* pointsXyz);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_stats(SceneHandle scene, ref Stats stats);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_read_desc(SceneHandle scene, ref SceneDesc desc);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_effect_stats(SceneHandle scene, Effect effect, ref EffectStats stats);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern IntPtr ent_effect_name(Effect effect);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_save_state(SceneHandle scene, byte* buffer, UIntPtr capacity,
                                                           out UIntPtr size);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_restore_state(SceneHandle scene, byte* buffer, UIntPtr size);

        // ---- environment ---------------------------------------------------------------------
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_obstacle_desc_init(ref ObstacleDesc desc, uint structSize);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_add_obstacle(SceneHandle scene, ref ObstacleDesc desc, out int obstacle);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_obstacle_set_pose(SceneHandle scene, int obstacle, Vec3* position,
                                                            Quat* orientation);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_obstacle_set_velocity(SceneHandle scene, int obstacle, Vec3* linear,
                                                                Vec3* angular);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_obstacle_set_friction(SceneHandle scene, int obstacle, double friction);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_remove_obstacle(SceneHandle scene, int obstacle);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_obstacle_count(SceneHandle scene, out uint count);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_obstacle_pose(SceneHandle scene, int obstacle, Vec3* position,
                                                        Quat* orientation);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_obstacle_mesh(SceneHandle scene, int obstacle, uint vertexCapacity,
                                                        double* verticesXyz, out uint vertexCount,
                                                        uint triangleCapacity, uint* triangles, out uint triangleCount);

        // ---- run-time changes ------------------------------------------------------------------
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_set_gravity(SceneHandle scene, Vec3* gravity);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_pin_point(SceneHandle scene, uint controlPoint, int obstacle);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_unpin_point(SceneHandle scene, uint controlPoint);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_attach_mesentery(SceneHandle scene, int obstacle);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_attach_clamped_end(SceneHandle scene, PinnedEnds ends, int obstacle);

        // ---- tools -------------------------------------------------------------------------------
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_desc_init(ref ToolDesc desc, uint structSize);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_add(SceneHandle scene, ref ToolDesc desc, out int tool);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_set_pose(SceneHandle scene, int tool, Vec3* position, Quat* orientation);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_wrench(SceneHandle scene, int tool, Vec3* force, Vec3* torque);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_grasp(SceneHandle scene, int tool);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_release(SceneHandle scene, int tool);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_state(SceneHandle scene, int tool, out int grasping);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_read_feedback(SceneHandle scene, int tool, ref ToolFeedback feedback);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_stiffness(SceneHandle scene, int tool, Matrix3* stiffness);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_read_stats(SceneHandle scene, int tool, ref ToolStats stats);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_read_desc(SceneHandle scene, int tool, ref ToolDesc desc);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_remove(SceneHandle scene, int tool);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_tool_count(SceneHandle scene, out int count);

        // ---- contacts --------------------------------------------------------------------------
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_contacts(SceneHandle scene, uint capacity, Contact* contacts,
                                                         out uint count);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_contact_summary(SceneHandle scene, ref ContactSummary summary);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_tool_read_contacts(SceneHandle scene, int tool, ref ToolContacts contacts);

        // ---- exposure ------------------------------------------------------------------------------
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_exposure_desc_init(ref ExposureDesc desc, uint structSize);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_exposure_create(SceneHandle scene, ref ExposureDesc desc,
                                                          out ExposureHandle exposure);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern void ent_exposure_destroy(IntPtr exposure);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_scene_exposure(SceneHandle scene, ExposureHandle exposure, Vec3* viewpoint,
                                                         ref ExposureResult result);

        // ---- skins -------------------------------------------------------------------------------
        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_skin_desc_init(ref SkinDesc desc, uint structSize);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_skin_create(SceneHandle scene, ref SkinDesc desc, out SkinHandle skin);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_skin_update(SkinHandle skin);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_skin_mesh(IntPtr skin, ref MeshView view);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern Status ent_skin_metrics(SkinHandle skin, ref SkinMetrics metrics);

        [DllImport(Library, CallingConvention = Cdecl)]
        internal static extern void ent_skin_destroy(IntPtr skin);
    }
}
