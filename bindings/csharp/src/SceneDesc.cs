// SPDX-License-Identifier: Apache-2.0
using System;
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>
    /// Everything needed to create a scene without JSON (ent_scene_desc). Start from
    /// <see cref="Default"/>, change what you need, then call <see cref="Scene.FromDescription"/>.
    /// The fields keep the header's names and units (include/enteron/enteron.h documents each
    /// one; docs/scene-json.md gives their plausible ranges). The three C pointers (the shape's
    /// points, the pinned points, the callbacks) are arguments of Scene.FromDescription instead.
    /// </summary>
    [CStruct("ent_scene_desc")]
    [StructLayout(LayoutKind.Sequential)]
    public struct SceneDesc
    {
        internal uint struct_size;
        /// <summary>The effects to simulate (default: stretch, bend, damping, gravity).</summary>
        public Effects effects;

        /// <summary>rest length of the axis, m (default 6)</summary>
        public double length_m;
        /// <summary>tube radius R, m (default 0.0125)</summary>
        public double radius_m;
        /// <summary>spline control points, >= 4 (default 240)</summary>
        public uint control_points;
        /// <summary>mass per unit length, kg/m (default 0.3)</summary>
        public double linear_density_kg_per_m;
        /// <summary>axial stiffness EA, N (default 100)</summary>
        public double stretch_stiffness_N;
        /// <summary>bending stiffness EI, N m^2 (default 2.5e-3)</summary>
        public double bend_stiffness_N_m2;

        /// <summary>initial shape (default helix)</summary>
        public Shape shape;
        /// <summary>line: start point; serpentine: centre; helix: centre of its base, m</summary>
        public Vec3 shape_center_m;
        /// <summary>line: direction (default +x)</summary>
        public Vec3 shape_direction;
        /// <summary>serpentine: length of each straight leg, m (default 0.3)</summary>
        public double shape_leg_length_m;
        /// <summary>serpentine: distance between legs, m, >= 2 R (default 0.05)</summary>
        public double shape_leg_spacing_m;
        /// <summary>helix: radius, m (default 0.1)</summary>
        public double shape_helix_radius_m;
        /// <summary>helix: rise per turn, m, >= 2 R (default 0.03)</summary>
        public double shape_helix_pitch_m;
        internal IntPtr shape_points_xyz_m;

        /// <summary>time integrator (default implicit Euler)</summary>
        public Integrator integrator;
        /// <summary>largest internal substep h, s (default 0.001)</summary>
        public double timestep_s;
        /// <summary>most substeps one step may take (default 1000)</summary>
        public uint max_substeps;
        /// <summary>times the guard may halve the substep before giving up (default 4)</summary>
        public uint max_subdivisions;
        /// <summary>a faster control point counts as an explosion, m/s (default 50)</summary>
        public double max_speed_m_per_s;

        /// <summary>gravity, m/s^2 (default 0, 0, -9.81)</summary>
        public Vec3 gravity_m_per_s2;

        /// <summary>drag per metre of axis per m/s (default 0.05)</summary>
        public double drag_N_s_per_m2;
        /// <summary>axial force per unit strain rate, N s (default 0.05)</summary>
        public double stretch_damping_N_s;
        /// <summary>bending moment per unit curvature rate, N m^2 s (default 0)</summary>
        public double bend_damping_N_m2_s;

        /// <summary>first end of the mesentery's root line, m</summary>
        public Vec3 mesentery_root_start_m;
        /// <summary>second end of the mesentery's root line, m</summary>
        public Vec3 mesentery_root_end_m;
        /// <summary>mesentery springs, spread evenly along the axis (default 60)</summary>
        public uint mesentery_attachments;
        /// <summary>stiffness of each spring, N/m (default 5)</summary>
        public double mesentery_stiffness_N_per_m;
        /// <summary>slack length of every spring, m; 0: each spring's initial length</summary>
        public double mesentery_rest_length_m;

        /// <summary>ends held at their initial position (default none)</summary>
        public PinnedEnds pinned_ends;
        internal IntPtr pinned_points;
        internal uint pinned_point_count;

        internal IntPtr callbacks;

        /// <summary>collision sphere spacing at rest, m, &lt;= R; 0: R / 2</summary>
        public double collision_sphere_spacing_m;
        /// <summary>normal stiffness of one sphere's contact, N/m (default 500)</summary>
        public double contact_stiffness_N_per_m;
        /// <summary>normal damping while approaching, N s/m (default 0.5)</summary>
        public double contact_damping_N_s_per_m;
        /// <summary>Coulomb friction coefficient (default 0.3)</summary>
        public double contact_friction;
        /// <summary>friction is viscous below about this sliding speed, m/s (default 0.01)</summary>
        public double contact_slip_speed_m_per_s;

        /// <summary>ends clamped: held in place with their tangent (default none)</summary>
        public PinnedEnds clamped_ends;

        // The properties along the length: set through Scene.FromDescription's profiles.
        internal IntPtr radius_profile_m;
        internal uint radius_profile_count;
        internal IntPtr linear_density_profile_kg_per_m;
        internal uint linear_density_profile_count;
        internal IntPtr stretch_stiffness_profile_N;
        internal uint stretch_stiffness_profile_count;
        internal IntPtr bend_stiffness_profile_N_m2;
        internal uint bend_stiffness_profile_count;

        // The fan mesentery's root and mapping and the pinned spans (the C fields of the same
        // names): mirrored for the layout; from C# a scene gives them in its JSON.
        internal IntPtr mesentery_root_points_m;
        internal uint mesentery_root_point_count;
        internal IntPtr mesentery_root_mapping;
        internal uint mesentery_root_mapping_count;
        internal IntPtr pinned_spans_m;
        internal uint pinned_span_count;

        /// <summary>The library's defaults (ent_scene_desc_init), struct_size set.</summary>
        public static SceneDesc Default()
        {
            var desc = new SceneDesc();
            EnteronException.Check(NativeMethods.ent_scene_desc_init(ref desc, StructSize<SceneDesc>.Value),
                                   "ent_scene_desc_init");
            return desc;
        }
    }

    /// <summary>
    /// Properties along the length (docs/scene-json.md, intestine.radius_profile), each in
    /// place of its constant in <see cref="SceneDesc"/>: pairs s (m, arc length from the first
    /// end at rest), value, flattened (s0, v0, s1, v1, ...); null: the constant.
    /// </summary>
    public sealed class Profiles
    {
        /// <summary>(s m, radius m) pairs.</summary>
        public double[] Radius;
        /// <summary>(s m, mass per metre kg/m) pairs.</summary>
        public double[] LinearDensity;
        /// <summary>(s m, axial stiffness EA N) pairs.</summary>
        public double[] StretchStiffness;
        /// <summary>(s m, bending stiffness EI N m^2) pairs.</summary>
        public double[] BendStiffness;
    }
}
