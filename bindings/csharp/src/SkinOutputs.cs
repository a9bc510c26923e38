// SPDX-License-Identifier: Apache-2.0
// What a skin reports: its mesh view (kept inside the binding: its pointers are valid only
// until the skin's next update) as a MeshInfo without pointers, and its metrics.
using System;
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>ent_mesh_view: pointers into the skin's buffers. Only Skin reads them, under its lease.</summary>
    [CStruct("ent_mesh_view")]
    [StructLayout(LayoutKind.Sequential)]
    internal struct MeshView
    {
        internal uint struct_size;
        internal uint vertex_count;
        internal uint triangle_count;
        internal IntPtr positions_xyz_m;
        internal IntPtr normals_xyz;
        internal IntPtr axis_u;
        internal IntPtr indices;
        internal double time_s;
        internal ulong updates;
        internal IntPtr around_v;
        internal IntPtr tangents_xyz;
        internal ulong topology_serial;
        internal int topology_changed;
        internal int stable_topology;
    }

    /// <summary>
    /// The shape of a skin's current mesh, without its arrays (<see cref="Skin.Mesh"/>): how
    /// large the arrays given to the Skin.Copy* methods must be, and whether the indices
    /// changed.
    /// </summary>
    public struct MeshInfo
    {
        /// <summary>vertices</summary>
        public int VertexCount;
        /// <summary>triangles (the indices hold 3 per triangle)</summary>
        public int TriangleCount;
        /// <summary>simulated time of the state the mesh was made from, s</summary>
        public double TimeSeconds;
        /// <summary>successful updates of the skin so far</summary>
        public ulong Updates;
        /// <summary>counts the updates that changed vertex_count or the indices: equal values, the same indices</summary>
        public ulong TopologySerial;
        /// <summary>the last update changed vertex_count or the indices: upload the indices again</summary>
        public bool TopologyChanged;
        /// <summary>the skin keeps its topology while the bowel moves (tube and convolution with stable_topology)</summary>
        public bool StableTopology;

        internal MeshInfo(ref MeshView view)
        {
            VertexCount = (int)view.vertex_count;
            TriangleCount = (int)view.triangle_count;
            TimeSeconds = view.time_s;
            Updates = view.updates;
            TopologySerial = view.topology_serial;
            TopologyChanged = view.topology_changed != 0;
            StableTopology = view.stable_topology != 0;
        }
    }

    /// <summary>How close the mesh is to the ideal tube of radius R (struct ent_skin_metrics; <see cref="Skin.GetMetrics"/>).</summary>
    [CStruct("ent_skin_metrics")]
    [StructLayout(LayoutKind.Sequential)]
    public struct SkinMetrics
    {
        internal uint struct_size;
        /// <summary>vertices</summary>
        public uint vertex_count;
        /// <summary>triangles</summary>
        public uint triangle_count;
        /// <summary>1 if every edge is shared by exactly two triangles</summary>
        public int watertight;
        /// <summary>edges of only one triangle</summary>
        public uint open_edges;
        /// <summary>edges of three or more triangles</summary>
        public uint nonmanifold_edges;
        /// <summary>vertices pulled into another fold</summary>
        public uint blended_vertices;
        /// <summary>triangles facing the axis (the tube's fold-over)</summary>
        public uint inverted_triangles;
        /// <summary>RMS of | |v - A(u)| - R | / R</summary>
        public double radius_error_rms;
        /// <summary>largest of those</summary>
        public double radius_error_max;
        /// <summary>RMS angle to the ideal tube's normal, rad</summary>
        public double normal_deviation_rms_rad;
        /// <summary>largest of those, rad</summary>
        public double normal_deviation_max_rad;
        /// <summary>enclosed volume, m^3</summary>
        public double volume_m3;
        /// <summary>relative volume error</summary>
        public double volume_error;
        /// <summary>arc length of the axis skinned, m</summary>
        public double axis_length_m;
        /// <summary>wall time of the last update, ns</summary>
        public ulong last_update_ns;
        /// <summary>RMS chord error of the triangles, in R</summary>
        public double facet_error_rms;
        /// <summary>largest of those</summary>
        public double facet_error_max;
        /// <summary>deepest vertex inside another fold's part of the mesh, in R (0 on contact surfaces)</summary>
        public double overlap_depth_max;
        /// <summary>area of triangles inside another fold's part of the mesh by more than R / 100, m^2</summary>
        public double overlap_area_m2;
        /// <summary>deepest vertex inside another fold's ideal tube, in R: how hard the folds press</summary>
        public double tube_overlap_depth_max;
        /// <summary>area of triangles inside another fold's ideal tube by more than R / 100, m^2</summary>
        public double tube_overlap_area_m2;
        /// <summary>largest distance from a vertex inside another fold's tube to that fold's skin, in R</summary>
        public double contact_gap_max;
        /// <summary>(V - V_tube) / V_tube: the volume the skin's shape adds or loses</summary>
        public double shape_volume_error;
        /// <summary>RMS radius error away from contacts and creases</summary>
        public double free_radius_error_rms;
        /// <summary>largest distance from a vertex to the previous update's mesh, in R</summary>
        public double vertex_motion_max;
        /// <summary>largest motion beyond what the tube around the vertex's axis point moved, in R: popping</summary>
        public double vertex_excess_motion_max;
        /// <summary>vertices free_radius_error_rms is over</summary>
        public uint free_vertex_count;
        /// <summary>1 if the motion measures compare with an update before</summary>
        public int has_previous_update;
    }
}
