// SPDX-License-Identifier: Apache-2.0
using System.Runtime.InteropServices;

namespace Enteron
{
    /// <summary>Counters and energies of the last published state (ent_stats; <see cref="Scene.GetStats"/>).</summary>
    [CStruct("ent_stats")]
    [StructLayout(LayoutKind.Sequential)]
    public struct Stats
    {
        internal uint struct_size;
        /// <summary>number of control points</summary>
        public uint control_points;
        /// <summary>simulated time, s</summary>
        public double time_s;
        /// <summary>successful steps</summary>
        public ulong steps;
        /// <summary>substeps taken by those steps (retries included)</summary>
        public ulong substeps;
        /// <summary>attempts the guard rejected and rolled back</summary>
        public ulong rollbacks;
        /// <summary>kinetic energy of the axis, J</summary>
        public double kinetic_energy_J;
        /// <summary>elastic + gravity + springs + contacts, J</summary>
        public double potential_energy_J;
        /// <summary>contacts in the last substep</summary>
        public uint contacts;
        /// <summary>deepest contact in the last substep, m</summary>
        public double max_penetration_m;
        /// <summary>wall time of the last step, ns</summary>
        public ulong last_step_ns;
        /// <summary>attempts of the last step: 1, or 1 + the guard's subdivisions (max_subdivisions + 1 for a failed step); 0 before the first step</summary>
        public uint last_step_attempts;
        /// <summary>substeps the last step integrated, its rejected attempts' included</summary>
        public uint last_step_substeps;
        /// <summary>the most Newton iterations one tool proxy's solve took in the last step</summary>
        public uint last_step_proxy_iterations;
        /// <summary>the proxies' force balances evaluated in the last step (each iteration and line-search halving)</summary>
        public uint last_step_proxy_evaluations;
        /// <summary>wall time of the longest step so far, ns</summary>
        public ulong max_step_ns;
        /// <summary>steps whose wall time exceeded the dt they simulated</summary>
        public ulong late_steps;
        /// <summary>successful steps that took more than one attempt</summary>
        public ulong subdivided_steps;
        /// <summary>tool proxy solves that ran out of iterations before their forces balanced</summary>
        public ulong proxy_unbalanced_solves;
        /// <summary>self-contact searches that listed the near pairs of every collision sphere</summary>
        public ulong full_contact_searches;
    }

    /// <summary>What one effect cost so far (ent_effect_stats; <see cref="Scene.GetEffectStats"/>).</summary>
    [CStruct("ent_effect_stats")]
    [StructLayout(LayoutKind.Sequential)]
    public struct EffectStats
    {
        internal uint struct_size;
        /// <summary>1 if the scene simulates this effect, else 0</summary>
        public int enabled;
        /// <summary>evaluations (an RK4 substep evaluates 4 times)</summary>
        public ulong calls;
        /// <summary>wall time spent in those evaluations, ns</summary>
        public ulong total_time_ns;
    }
}
