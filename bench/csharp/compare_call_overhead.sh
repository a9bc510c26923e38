#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The per-call cost of Enteron's calls through C# (Enteron.dll under Mono) against C, in the
# same minutes: runs the C program (call_overhead.c), the C# one (CallOverhead.cs) under
# Mono's default thread suspend mode (hybrid, in Mono 6.8) and again under
# MONO_THREADS_SUSPEND=preemptive, alternately, RUNS times each, and prints a Markdown table
# of the medians of their per-run medians and of the differences (what the binding adds).
#
#   bench/csharp/compare_call_overhead.sh [BUILD_DIR] [RUNS]     (defaults: build, 7)
#
# Needs the targets enteron_call_overhead and enteron_csharp_call_overhead (a build with
# ENTERON_BUILD_BENCH and the C# binding). Timings on a shared machine are noisy: say so
# next to any figure taken from it.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-$here/../../build}"
runs="${2:-7}"
c_program="$build/bench/enteron_call_overhead"
csharp_program="$build/bindings/csharp/CallOverhead.exe"
scene="$here/call_overhead_scene.json"
for program in "$c_program" "$csharp_program"; do
  [[ -f "$program" ]] || { echo "compare_call_overhead.sh: $program is not built" >&2; exit 1; }
done
c_lines=()
hybrid_lines=()
preemptive_lines=()
for ((run = 1; run <= runs; ++run)); do
  c_lines+=("$("$c_program" "$scene")")
  hybrid_lines+=("$(env -u MONO_THREADS_SUSPEND mono "$csharp_program" "$scene")")
  preemptive_lines+=("$(MONO_THREADS_SUSPEND=preemptive mono "$csharp_program" "$scene")")
  echo "run $run: ${c_lines[-1]} | ${hybrid_lines[-1]} | preemptive ${preemptive_lines[-1]}" >&2
done
/usr/bin/python3 - "$runs" "${c_lines[@]}" "${hybrid_lines[@]}" "${preemptive_lines[@]}" <<'PY'
import statistics
import sys

runs = int(sys.argv[1])
lines = sys.argv[2:]
def figures(line):
    words = line.split()[1:]
    return {words[i]: float(words[i + 1]) for i in range(0, len(words), 2)}
c, hybrid, preemptive = ([figures(line) for line in lines[k * runs:(k + 1) * runs]] for k in range(3))
names = {"version_ns": "`ent_version` (an empty call) / `Library.Version`",
         "step_ns": "`ent_scene_step` / `Scene.Step` (4-point bowel, no effect)",
         "read_feedback_ns": "`ent_tool_read_feedback` / `Tool.ReadFeedback(ref)`"}
print("| call | C, ns | C# (Mono's default suspend), ns | C# - C | C# (`MONO_THREADS_SUSPEND=preemptive`), ns | C# - C |")
print("|---|---|---|---|---|---|")
for key, name in names.items():
    a = statistics.median(run[key] for run in c)
    b = statistics.median(run[key] for run in hybrid)
    p = statistics.median(run[key] for run in preemptive)
    print("| %s | %.1f | %.1f | %+.1f | %.1f | %+.1f |" % (name, a, b, b - a, p, p - a))
print()
print("Medians of %d alternated runs of each (each run: the median of 21 rounds of 20000 calls)." % runs)
PY
