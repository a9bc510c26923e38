// SPDX-License-Identifier: Apache-2.0
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>
    /// How to skin (ent_skin_desc; docs/skinning.md). Lengths are in units of the bowel's
    /// radius R. Start from <see cref="Default"/>, then <c>new Skin(scene, desc)</c>.
    /// </summary>
    [CStruct("ent_skin_desc")]
    [StructLayout(LayoutKind.Sequential)]
    public struct SkinDesc
    {
        internal uint struct_size;
        /// <summary>the method (default convolution)</summary>
        public SkinMethod method;
        /// <summary>tube, convolution: vertices around each ring, 3 to 1024 (default 16)</summary>
        public uint segments;
        /// <summary>tube, convolution: arc length between rings, in R (default 0.5)</summary>
        public double ring_spacing_radii;
        /// <summary>tube, convolution: rings of each end cap (default 4)</summary>
        public uint cap_rings;
        /// <summary>point_skeleton, convolution: skeleton spacing, in R (default 0.25)</summary>
        public double skeleton_spacing_radii;
        /// <summary>point_skeleton: marching-cubes voxel, in R (default 1/3)</summary>
        public double voxel_size_radii;
        /// <summary>point_skeleton, convolution: half-width of local blending, in R (default 1)</summary>
        public double window_radii;
        /// <summary>convolution: level of detail along the axis, in R (default 0: even rings)</summary>
        public double ring_chord_error_radii;
        /// <summary>tube, convolution: 1 (default) keeps vertex count and indices while the bowel moves</summary>
        public int stable_topology;
        /// <summary>point_skeleton, convolution: 1 (default) folds pressed together meet on a contact surface, with a bulge beside it, instead of passing through each other</summary>
        public int contact_surfaces;
        /// <summary>convolution: 0 (default) even segment ends; above 0 (in R, up to 0.1) they follow the curvature, each chord within this of the axis</summary>
        public double skeleton_chord_error_radii;

        /// <summary>The library's defaults (ent_skin_desc_init) with this method.</summary>
        public static SkinDesc Default(SkinMethod method = SkinMethod.Convolution)
        {
            var desc = new SkinDesc();
            EnteronException.Check(NativeMethods.ent_skin_desc_init(ref desc, StructSize<SkinDesc>.Value),
                                   "ent_skin_desc_init");
            desc.method = method;
            return desc;
        }
    }
}
