#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The parts of the LCM round trip, each alone (bench/lcm/latency_parts.cpp), inside a
# network namespace made here (nothing leaves it): the timer's wake-up, the physics ->
# publishing thread hand-off (on one core and across two), raw UDP multicast ping-pong and
# LCM udpm ping-pong between two processes pinned to their own cores. Prints one markdown
# table row per part.
#   latency_parts.sh BUILD_DIR SECONDS [--fifo P]
#     --fifo P   every measuring thread under SCHED_FIFO P (needs root)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$(cd "${1:?usage: latency_parts.sh BUILD_DIR SECONDS [--fifo P]}" && pwd)"
seconds="${2:?SECONDS}"
shift 2
fifo=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --fifo) fifo=(--fifo "$2"); shift 2 ;;
    *) echo "latency_parts.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
source "$root/tests/lcm/network_namespace.sh"
enter_network_namespace latency_parts "$build" "$seconds" "$@"
parts="$build/bench/lcm/enteron_lcm_latency_parts"
last_cpu=$(( $(nproc) - 1 ))

echo "| part | samples | median us | p99 | p99.9 | largest | over 100 us | over 1 ms |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
"$parts" timer --cpu 0 --seconds "$seconds" "${fifo[@]}"
"$parts" handoff --cpu 0 --seconds "$seconds" "${fifo[@]}"
"$parts" handoff --cpu 0 --peer-cpu "$last_cpu" --seconds "$seconds" "${fifo[@]}"
for part in udp lcm; do
  "$parts" "$part" --role pong --cpu "$last_cpu" --seconds "$seconds" "${fifo[@]}" &
  pong=$!
  "$parts" "$part" --role ping --cpu 0 --seconds "$seconds" "${fifo[@]}"
  wait "$pong"
done
