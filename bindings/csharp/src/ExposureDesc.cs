// SPDX-License-Identifier: Apache-2.0
using System;
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>
    /// How to sample a target for <see cref="Exposure"/> (ent_exposure_desc): start from
    /// <see cref="Default"/>, set the frame and the sampling, then <c>new Exposure(scene,
    /// desc, pointsXyz, triangles, weights)</c>. The target's points, triangles and weights
    /// are arguments of the Exposure constructor (the C pointers and counts are set there,
    /// for the call only: the library copies them).
    /// </summary>
    [CStruct("ent_exposure_desc")]
    [StructLayout(LayoutKind.Sequential)]
    public struct ExposureDesc
    {
        internal uint struct_size;
        internal IntPtr points_xyz_m;
        internal uint point_count;
        internal IntPtr triangles;
        internal uint triangle_count;
        internal IntPtr weights;
        /// <summary>a patch: each triangle's edge cut into this many parts, 1 to 32 (default 4: 16 samples a triangle)</summary>
        public uint samples_per_edge;
        /// <summary>the frame of the points: <see cref="Scene.NoObstacle"/> (the world; default) or an obstacle's index (the target moves with it)</summary>
        public int obstacle;
        /// <summary>the bowel's axis sampled at this many chords per spline segment, 1 to 64 (default 4)</summary>
        public uint axis_chords_per_segment;

        /// <summary>The library's defaults (ent_exposure_desc_init): world frame, 4 samples per edge, 4 chords per segment.</summary>
        public static ExposureDesc Default()
        {
            var desc = new ExposureDesc();
            EnteronException.Check(NativeMethods.ent_exposure_desc_init(ref desc, StructSize<ExposureDesc>.Value),
                                   "ent_exposure_desc_init");
            return desc;
        }
    }
}
