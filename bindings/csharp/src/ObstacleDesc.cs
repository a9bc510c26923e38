// SPDX-License-Identifier: Apache-2.0
using System;
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>
    /// A rigid obstacle (ent_obstacle_desc): start from <see cref="Default"/>, set the kind
    /// and its fields, then <see cref="Scene.AddObstacle"/>. A mesh's vertices and triangles
    /// are arguments of AddObstacle (the C pointers are set there, for the call only).
    /// </summary>
    [CStruct("ent_obstacle_desc")]
    [StructLayout(LayoutKind.Sequential)]
    public struct ObstacleDesc
    {
        internal uint struct_size;
        /// <summary>the kind (default box inside)</summary>
        public ObstacleKind kind;
        /// <summary>box, sphere: centre; plane: a point of the plane, m</summary>
        public Vec3 center_m;
        /// <summary>box: half of its size along x, y, z, each > 0, m (default 0.12)</summary>
        public Vec3 half_extents_m;
        /// <summary>plane: normal toward the bowel's side (default 0, 0, 1)</summary>
        public Vec3 normal;
        /// <summary>capsule: first end of its axis, m</summary>
        public Vec3 start_m;
        /// <summary>capsule: second end of its axis, m (default 0, 0, 0.1)</summary>
        public Vec3 end_m;
        /// <summary>sphere, capsule: radius, m (default 0.05)</summary>
        public double radius_m;
        internal IntPtr mesh_vertices_xyz_m;
        internal uint mesh_vertex_count;
        internal IntPtr mesh_triangles;
        internal uint mesh_triangle_count;
        /// <summary>mesh: edge of the distance field's voxels, m; 0: R / 4</summary>
        public double mesh_voxel_size_m;
        /// <summary>origin of the obstacle's frame, m</summary>
        public Vec3 position_m;
        /// <summary>orientation of its frame (default identity)</summary>
        public Quat orientation_wxyz;
        /// <summary>Coulomb friction of its contacts, >= 0; negative: the scene's (default -1)</summary>
        public double friction;

        /// <summary>The library's defaults (ent_obstacle_desc_init) with this kind.</summary>
        public static ObstacleDesc Default(ObstacleKind kind = ObstacleKind.BoxInside)
        {
            var desc = new ObstacleDesc();
            EnteronException.Check(NativeMethods.ent_obstacle_desc_init(ref desc, StructSize<ObstacleDesc>.Value),
                                   "ent_obstacle_desc_init");
            desc.kind = kind;
            return desc;
        }
    }
}
