#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The command-to-feedback round trip between two processes over udpm, inside a network
# namespace made here (nothing leaves it): enteron-lcm-server runs the demo scene
# (examples/lcm/scenes/demo.json) and the driver-side example sweeps its tool through the
# pile at 1 kHz, phase-locked to the feedback (or --free-running), for SECONDS. Prints the
# device's line (round trip median, p99, max; feedback ticks missed) and the server's
# (missed deadlines, step times), and how long the server took to stop after SIGTERM.
#   udpm_round_trip.sh BUILD_DIR SECONDS [--realtime P] [--free-running]
#     --realtime P   the server's --realtime P (SCHED_FIFO, mlockall) and the device under
#                    chrt -f P-10 (needs root)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$(cd "${1:?usage: udpm_round_trip.sh BUILD_DIR SECONDS [--realtime P] [--free-running]}" && pwd)"
seconds="${2:?SECONDS}"
shift 2
server_flags=()
device_prefix=()
device_flags=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --realtime) server_flags+=(--realtime "$2"); device_prefix=(chrt -f "$(($2 - 10))"); shift 2 ;;
    --free-running) device_flags+=(--free-running); shift ;;
    *) echo "udpm_round_trip.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
source "$root/tests/lcm/network_namespace.sh"
enter_network_namespace udpm_round_trip "$build" "$seconds" "$@"
url='udpm://239.255.76.67:7667?ttl=0'
work="$(mktemp -d)"
trap 'jobs -p | xargs -r kill 2>/dev/null || true; rm -rf "$work"' EXIT

"$build/apps/lcm/enteron-lcm-server" --scene "$root/examples/lcm/scenes/demo.json" --lcm-url "$url" \
  --workspace-scale 0.001 --quiet "${server_flags[@]}" >"$work/server.out" 2>&1 &
server=$!
for _ in $(seq 100); do grep -q serving "$work/server.out" && break; sleep 0.05; done
"${device_prefix[@]}" "$build/examples/lcm/enteron_lcm_haptic_device" --lcm-url "$url" --script sweep \
  --seconds "$seconds" --quiet "${device_flags[@]}" | grep "feedback ticks"
sent="$(date +%s%N)"
kill -TERM "$server"
wait "$server"
echo "server: stopped $(( ($(date +%s%N) - sent) / 1000000 )) ms after SIGTERM"
grep -E "missed deadlines|stopped|SCHED_FIFO|mlockall" "$work/server.out"
