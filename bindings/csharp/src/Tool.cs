// SPDX-License-Identifier: Apache-2.0
using System;

namespace Enteron
{
    /// <summary>
    /// A surgical tool of a scene (ent_tool_*): a capsule driven by the caller that pushes
    /// and grasps the bowel. Made by <see cref="Scene.AddTool"/> or <see cref="Scene.GetTool"/>.
    /// Every call is safe from any thread at any time (a haptic thread while another steps):
    /// the commands go into the tool's mailbox, which the next step takes (the last one
    /// posted wins), and the reads copy the last published step. None waits for the step
    /// and none allocates on the managed heap. Only <see cref="Remove"/> is a driving call.
    /// <code>
    /// tool.SetPose(devicePosition, deviceOrientation);      // haptic thread, 1 kHz
    /// ToolFeedback feedback = tool.ReadFeedback();
    /// device.Render(feedback.force_N, feedback.stiffness_N_per_m);
    /// </code>
    /// </summary>
    public sealed unsafe class Tool
    {
        internal Tool(Scene scene, int id)
        {
            Scene = scene;
            Id = id;
        }

        /// <summary>The scene the tool belongs to.</summary>
        public Scene Scene { get; private set; }

        /// <summary>The tool's id: 0, 1, ... in order of addition (never reused).</summary>
        public int Id { get; private set; }

        /// <summary>
        /// Where the tip is at the end of the next step, m, and the orientation (the shaft runs
        /// from the tip along the orientation's local +z) (ent_tool_set_pose). The tool moves
        /// there continuously during that step.
        /// </summary>
        /// <exception cref="EnteronException">InvalidArgument (non-finite, zero quaternion), NotFound.</exception>
        public void SetPose(Vec3 position_m, Quat orientation)
        {
            EnteronException.Check(NativeMethods.ent_tool_set_pose(Scene.Handle, Id, &position_m, &orientation),
                                   "ent_tool_set_pose");
        }

        /// <summary>Grasps the bowel at the start of the next step: the nearest point within reach, if any (ent_tool_grasp).</summary>
        public void Grasp()
        {
            EnteronException.Check(NativeMethods.ent_tool_grasp(Scene.Handle, Id), "ent_tool_grasp");
        }

        /// <summary>Releases what the tool holds at the start of the next step (ent_tool_release).</summary>
        public void Release()
        {
            EnteronException.Check(NativeMethods.ent_tool_release(Scene.Handle, Id), "ent_tool_release");
        }

        /// <summary>Whether a grasp holds in the last published step (ent_tool_state).</summary>
        public bool IsGrasping
        {
            get
            {
                int grasping;
                EnteronException.Check(NativeMethods.ent_tool_state(Scene.Handle, Id, out grasping), "ent_tool_state");
                return grasping != 0;
            }
        }

        /// <summary>What the tool felt and did in the last published step, from one snapshot (ent_tool_read_feedback).</summary>
        public ToolFeedback ReadFeedback()
        {
            var feedback = new ToolFeedback();
            ReadFeedback(ref feedback);
            return feedback;
        }

        /// <summary>As <see cref="ReadFeedback()"/>, into the caller's struct.</summary>
        public void ReadFeedback(ref ToolFeedback feedback)
        {
            feedback.struct_size = StructSize<ToolFeedback>.Value;
            EnteronException.Check(NativeMethods.ent_tool_read_feedback(Scene.Handle, Id, ref feedback), "ent_tool_read_feedback");
        }

        /// <summary>The force (N) and torque about the tip (N m) of the bowel on the tool in the last step (ent_tool_wrench).</summary>
        public void GetWrench(out Vec3 force_N, out Vec3 torque_Nm)
        {
            Vec3 force, torque;
            EnteronException.Check(NativeMethods.ent_tool_wrench(Scene.Handle, Id, &force, &torque), "ent_tool_wrench");
            force_N = force;
            torque_Nm = torque;
        }

        /// <summary>
        /// The local stiffness dF/dx at the last published step, N/m, row-major
        /// (ent_tool_stiffness): a device loop faster than the physics renders F + K (x - x_k).
        /// </summary>
        public Matrix3 Stiffness()
        {
            Matrix3 stiffness;
            EnteronException.Check(NativeMethods.ent_tool_stiffness(Scene.Handle, Id, &stiffness), "ent_tool_stiffness");
            return stiffness;
        }

        /// <summary>The settings the tool was added with and the pose it was added at (ent_tool_read_desc).</summary>
        public ToolDesc ReadDescription()
        {
            ToolDesc desc = ToolDesc.Default();
            EnteronException.Check(NativeMethods.ent_tool_read_desc(Scene.Handle, Id, ref desc), "ent_tool_read_desc");
            return desc;
        }

        /// <summary>The tool's passivity observer and counters since it was added (ent_tool_read_stats).</summary>
        public ToolStats ReadStats()
        {
            var stats = new ToolStats();
            stats.struct_size = StructSize<ToolStats>.Value;
            EnteronException.Check(NativeMethods.ent_tool_read_stats(Scene.Handle, Id, ref stats), "ent_tool_read_stats");
            return stats;
        }

        /// <summary>
        /// What the tool touches and holds in the last published step (ent_tool_read_contacts).
        /// The ranges of u it touches, first and last u of each, go into
        /// <paramref name="rangesU"/> (its capacity: Length / 2 ranges; null for none);
        /// range_count may exceed that capacity, and then only the first ranges are written.
        /// </summary>
        public ToolContacts ReadContacts(double[] rangesU = null)
        {
            var contacts = new ToolContacts();
            contacts.struct_size = StructSize<ToolContacts>.Value;
            fixed (double* ranges = rangesU)
            {
                contacts.range_capacity = ranges == null ? 0u : (uint)(rangesU.Length / 2);
                contacts.ranges_u = (IntPtr)ranges;
                EnteronException.Check(NativeMethods.ent_tool_read_contacts(Scene.Handle, Id, ref contacts),
                                       "ent_tool_read_contacts");
            }
            contacts.ranges_u = IntPtr.Zero;  // the array is unpinned now
            return contacts;
        }

        /// <summary>
        /// Removes the tool: from the next step it touches nothing and lets go; its id answers
        /// NotFound from then on (ent_tool_remove). A driving call.
        /// </summary>
        public void Remove()
        {
            EnteronException.Check(NativeMethods.ent_tool_remove(Scene.Handle, Id), "ent_tool_remove");
        }
    }
}
