// SPDX-License-Identifier: Apache-2.0
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>
    /// One contact of the bowel in the last published step (ent_contact): where on the bowel
    /// (u in [0, 1] along it), what it touches, the point, normal, depth and force.
    /// <see cref="Scene.ReadContacts"/> fills an array of them.
    /// </summary>
    [CStruct("ent_contact")]
    [StructLayout(LayoutKind.Sequential)]
    public struct Contact
    {
        internal uint struct_size;
        /// <summary>what the bowel touches</summary>
        public ContactKind kind;
        /// <summary>the obstacle's index or the tool's id; -1 for a self-contact</summary>
        public int index;
        /// <summary>where on the bowel, in [0, 1]</summary>
        public double u;
        /// <summary>self-contact: where the other fold touches (> u); else -1</summary>
        public double other_u;
        /// <summary>the contact point, m</summary>
        public Vec3 point_m;
        /// <summary>unit normal pushing the bowel at u away from what it touches</summary>
        public Vec3 normal;
        /// <summary>penetration, m, > 0</summary>
        public double depth_m;
        /// <summary>force on the bowel at u, N</summary>
        public Vec3 force_N;
    }

    /// <summary>The bowel's contacts and stretch in the last published step (ent_contact_summary).</summary>
    [CStruct("ent_contact_summary")]
    [StructLayout(LayoutKind.Sequential)]
    public struct ContactSummary
    {
        internal uint struct_size;
        /// <summary>the most contacts a step lists: size a Contact[] with it once</summary>
        public uint capacity;
        /// <summary>contacts <see cref="Scene.ReadContacts"/> gives for this step</summary>
        public uint listed;
        /// <summary>contacts found: more than listed when the list was full</summary>
        public uint found;
        /// <summary>self-contacts found</summary>
        public uint self_contacts;
        /// <summary>obstacle contacts found</summary>
        public uint obstacle_contacts;
        /// <summary>tool contacts found</summary>
        public uint tool_contacts;
        /// <summary>the largest |force| of any contact found, N</summary>
        public double largest_force_N;
        /// <summary>where on the bowel (u in [0, 1])</summary>
        public double largest_force_u;
        /// <summary>the largest stretch of a segment (0.05: 5 % longer than at rest)</summary>
        public double largest_stretch;
        /// <summary>where (u in [0, 1])</summary>
        public double largest_stretch_u;
        /// <summary>simulated time of the published state, s</summary>
        public double time_s;
        /// <summary>its successful step count</summary>
        public ulong steps;
    }
}
