// SPDX-License-Identifier: Apache-2.0
// What a tool reports from the last published step: the structs of ent_tool_read_feedback,
// ent_tool_read_stats and ent_tool_read_contacts. Read them with the Tool's methods, which
// set struct_size and allocate nothing.
using System;
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>What a tool felt and did in the last published step (ent_tool_feedback): what a haptic loop renders.</summary>
    [CStruct("ent_tool_feedback")]
    [StructLayout(LayoutKind.Sequential)]
    public struct ToolFeedback
    {
        internal uint struct_size;
        /// <summary>1 while a grasp holds, else 0</summary>
        public int grasping;
        /// <summary>force of the bowel on the tool, N, never above max_force_N</summary>
        public Vec3 force_N;
        /// <summary>torque of the bowel on the tool about its tip, N m</summary>
        public Vec3 torque_Nm;
        /// <summary>collision spheres touching the tool</summary>
        public uint contacts;
        /// <summary>simulated time of the published state, s</summary>
        public double time_s;
        /// <summary>successful steps at that state: a new value, a new step</summary>
        public ulong steps;
        /// <summary>d(force_N)/d(tip position), N/m (as <see cref="Tool.Stiffness"/>)</summary>
        public Matrix3 stiffness_N_per_m;
        /// <summary>the tip of the tool in the scene (the proxy's), m</summary>
        public Vec3 proxy_position_m;
        /// <summary>the tip the caller commanded for that step, m</summary>
        public Vec3 commanded_position_m;
        /// <summary>the commanded orientation for that step</summary>
        public Quat orientation_wxyz;
        /// <summary>1 if max_force_N bounded the tool's force in that step, else 0</summary>
        public int saturated;

        /// <summary>grasping != 0</summary>
        public bool IsGrasping
        {
            get { return grasping != 0; }
        }

        /// <summary>saturated != 0: the force is the tool's max_force_N, not what the contacts asked for</summary>
        public bool IsSaturated
        {
            get { return saturated != 0; }
        }
    }

    /// <summary>A tool's passivity observer and counters since it was added (ent_tool_stats).</summary>
    [CStruct("ent_tool_stats")]
    [StructLayout(LayoutKind.Sequential)]
    public struct ToolStats
    {
        internal uint struct_size;
        /// <summary>1 while a grasp holds, else 0</summary>
        public int grasping;
        /// <summary>collision spheres touching the tool in the last step</summary>
        public uint contacts;
        internal uint reserved;
        /// <summary>work the tool did on the scene, J</summary>
        public double energy_in_J;
        /// <summary>work the scene did on the tool, J</summary>
        public double energy_out_J;
        /// <summary>energy the passivity limiter took out, J</summary>
        public double limiter_energy_J;
        /// <summary>largest change of the rendered force from one step to the next, N</summary>
        public double largest_force_change_N;
        /// <summary>successful scene steps at that state</summary>
        public ulong steps;
    }

    /// <summary>
    /// What one tool touches and holds in the last published step (ent_tool_contacts). The
    /// ranges of u it touches go into the array given to <see cref="Tool.ReadContacts(double[])"/>.
    /// </summary>
    [CStruct("ent_tool_contacts")]
    [StructLayout(LayoutKind.Sequential)]
    public struct ToolContacts
    {
        internal uint struct_size;
        internal uint range_capacity;
        internal IntPtr ranges_u;
        /// <summary>ranges touched (only the first capacity of them were written)</summary>
        public uint range_count;
        /// <summary>collision spheres touching the tool</summary>
        public uint contacts;
        /// <summary>1 while a grasp holds</summary>
        public int grasping;
        /// <summary>where the grasp took hold (u in [0, 1]) while grasping; else -1</summary>
        public double grasp_u;
        /// <summary>the largest |force| of one of its contacts, N</summary>
        public double largest_force_N;
        /// <summary>the impulse of the bowel's contacts on the tool since it was added, N s</summary>
        public Vec3 contact_impulse_Ns;
        /// <summary>the same with each step's force magnitude, N s</summary>
        public double contact_impulse_magnitude_Ns;
        /// <summary>simulated time of the published state, s</summary>
        public double time_s;
        /// <summary>its successful step count</summary>
        public ulong steps;
    }
}
