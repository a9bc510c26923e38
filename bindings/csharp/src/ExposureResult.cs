// SPDX-License-Identifier: Apache-2.0
using System;
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>
    /// What <see cref="Exposure.Measure"/> found (ent_exposure_result). The spans of the bowel
    /// that hide part of the target, and the fraction seen of each point or triangle, go into
    /// the arrays given to Measure; this struct holds the rest.
    /// </summary>
    [CStruct("ent_exposure_result")]
    [StructLayout(LayoutKind.Sequential)]
    public struct ExposureResult
    {
        internal uint struct_size;
        internal uint span_capacity;
        internal IntPtr spans_u;
        internal IntPtr span_hidden_fractions;
        internal IntPtr span_intestines;
        internal IntPtr element_visible;
        /// <summary>the weight of the target seen over its total weight, 0 to 1</summary>
        public double visible_fraction;
        /// <summary>spans of the bowel that hide part of the target (only the first capacity of them were written)</summary>
        public uint span_count;
        /// <summary>sample points of the target (points, or triangles x samples_per_edge^2)</summary>
        public uint samples;
        /// <summary>of those, hidden by the bowel</summary>
        public uint hidden_samples;
        /// <summary>simulated time of the published state measured, s</summary>
        public double time_s;
        /// <summary>its successful step count</summary>
        public ulong steps;
    }
}
