// SPDX-License-Identifier: Apache-2.0
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>
    /// A surgical tool (ent_tool_desc): a capsule whose tip is at position_m and whose shaft
    /// runs back along the orientation's local +z for length_m. Start from <see cref="Default"/>,
    /// then <see cref="Scene.AddTool"/>. docs/haptics.md explains the modes and the coupling.
    /// </summary>
    [CStruct("ent_tool_desc")]
    [StructLayout(LayoutKind.Sequential)]
    public struct ToolDesc
    {
        internal uint struct_size;
        /// <summary>shaft radius, m (default 0.005)</summary>
        public double radius_m;
        /// <summary>shaft length from the tip along local +z, m (default 0.3)</summary>
        public double length_m;
        /// <summary>bound of the force the tool exerts and reports, N (default 5)</summary>
        public double max_force_N;
        /// <summary>grasp reach beyond touching, m (default 0.005)</summary>
        public double grasp_margin_m;
        /// <summary>stiffness of the grasp spring, N/m (default 200)</summary>
        public double grasp_stiffness_N_per_m;
        /// <summary>damping of the grasp spring, N s/m (default 2)</summary>
        public double grasp_damping_N_s_per_m;
        /// <summary>initial tip position, m</summary>
        public Vec3 position_m;
        /// <summary>initial orientation (default identity: shaft straight up from the tip)</summary>
        public Quat orientation_wxyz;
        /// <summary>proxy (default) or direct</summary>
        public ToolMode mode;
        /// <summary>1: the time-domain passivity controller keeps the tool passive; 0 (default): off</summary>
        public int passivity_limiter;
        /// <summary>proxy mode: the virtual coupling's spring, N/m (default 1000)</summary>
        public double coupling_stiffness_N_per_m;
        /// <summary>proxy mode: the coupling's damper, N s/m (default 1)</summary>
        public double coupling_damping_N_s_per_m;
        /// <summary>Coulomb coefficient of this tool's contacts; &lt; 0 (default -1): the scene's</summary>
        public double friction;
        /// <summary>a grasper's jaws: the last jaw_length_m of the shaft, m (default 0: a grasp takes what lies nearest the tip)</summary>
        public double jaw_length_m;
        /// <summary>how wide the jaws open, across the tool's local x axis, m (default 0)</summary>
        public double jaw_opening_m;
        /// <summary>a retractor's blade: the first blade_length_m of the shaft widened to this across local x, m (default 0: no blade)</summary>
        public double blade_width_m;
        /// <summary>the blade's length from the tip, m (default 0)</summary>
        public double blade_length_m;

        /// <summary>The library's defaults (ent_tool_desc_init).</summary>
        public static ToolDesc Default()
        {
            var desc = new ToolDesc();
            EnteronException.Check(NativeMethods.ent_tool_desc_init(ref desc, StructSize<ToolDesc>.Value),
                                   "ent_tool_desc_init");
            return desc;
        }
    }
}
