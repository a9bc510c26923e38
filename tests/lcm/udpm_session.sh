#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# lcm.udpm_session: enteron-lcm-server as a separate process over udpm, in a network
# namespace made here (nothing can leave it), with the driver-side example as the device
# (examples/lcm/haptic_device.c, millimetres mapped by --workspace-scale 0.001):
#   - the device pushes the bowel aside, grasps it and lifts it: its feedback arrives every
#     tick (no tick missed) and the grasp holds through the lift;
#   - lcm-logger records the session; the Python reader decodes it and plot_log.py plots it;
#   - SIGTERM stops the server with exit status 0 (the time it took is printed; the 100 ms
#     target is the benchmark's to measure, bench/lcm);
#   - the server's journal replays bit for bit (enteron-lcm-replay).
# Exits 77 (ctest: skipped) with the reason where a network namespace cannot be made.
#   udpm_session.sh WORK_DIR
# Environment: SERVER, REPLAY, DEVICE, SCENE, PLOT, TYPES, LCM_LOGGER (empty: no recording).
set -euo pipefail
work="${1:?usage: udpm_session.sh WORK_DIR}"
fail() { echo "lcm.udpm_session: FAILED: $*" >&2; exit 1; }

source "$(dirname "${BASH_SOURCE[0]}")/network_namespace.sh"
enter_network_namespace lcm.udpm_session "$@"
url='udpm://239.255.76.67:7667?ttl=0'

rm -rf "$work"
mkdir -p "$work"
cleanup() { jobs -p | xargs -r kill 2>/dev/null || true; }
trap cleanup EXIT

if [[ -n "${LCM_LOGGER:-}" ]]; then
  "$LCM_LOGGER" --quiet --lcm-url="$url" "$work/session.lcmlog" >"$work/logger.out" 2>&1 &
  logger=$!
fi
"$SERVER" --scene "$SCENE" --lcm-url "$url" --workspace-scale 0.001 --journal "$work/journal.lcmlog" --quiet \
  >"$work/server.out" 2>&1 &
server=$!
for _ in $(seq 100); do
  grep -q "serving" "$work/server.out" && break
  kill -0 "$server" 2>/dev/null || { cat "$work/server.out"; fail "the server did not start"; }
  sleep 0.05
done

"$DEVICE" --lcm-url "$url" --seconds 3 --quiet >"$work/device.out" 2>&1 || { cat "$work/device.out"; fail "the device"; }
cat "$work/device.out"
summary="$(grep "feedback ticks" "$work/device.out")"
ticks="$(sed -n 's/.* \([0-9]*\) feedback ticks.*/\1/p' <<<"$summary")"
# How many ticks fit in 3 s of wall time depends on the machine's load; that every tick
# the server sent arrived, in order, is what this test checks (the rate is bench/lcm's).
[[ "$ticks" -gt 0 ]] || fail "no feedback tick in 3 s"
grep -q "(0 missed)" <<<"$summary" || fail "the device missed feedback ticks: $summary"
grep -q "grasped yes, held through the lift yes" <<<"$summary" || fail "the grasp did not hold: $summary"

sent="$(date +%s%N)"
kill -TERM "$server"
status=0
wait "$server" || status=$?
stopped_ms=$(( ($(date +%s%N) - sent) / 1000000 ))
cat "$work/server.out"
[[ $status -eq 0 ]] || fail "the server exited with status $status after SIGTERM"
grep -q "stopped after SIGTERM" "$work/server.out" || fail "the server did not report its stop"
echo "lcm.udpm_session: the server stopped $stopped_ms ms after SIGTERM, exit status 0"
# A bound against a hang only: the 100 ms target is measured by bench/lcm, not here.
(( stopped_ms < 30000 )) || fail "the server took $stopped_ms ms to stop"

if [[ -n "${LCM_LOGGER:-}" ]]; then
  kill -INT "$logger"
  wait "$logger" || true
  plot_line="$(PYTHONPATH="$TYPES" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 "$PLOT" "$work/session.lcmlog" \
               --out "$work/session.png")" || fail "plot_log.py could not read the recording"
  echo "$plot_line"
  # lcm-logger is LCM's process, not ours: on a loaded machine it is not scheduled in time and
  # the kernel drops what overflows its socket. The device's own count above is the check;
  # here the recording must decode and hold feedback ticks.
  grep -q " [1-9][0-9]* feedback ticks of tool 0" <<<"$plot_line" || fail "the recording holds no feedback: $plot_line"
  [[ -s "$work/session.png" ]] || fail "no plot written"
else
  echo "lcm.udpm_session: no lcm-logger: the recording and its plot are not tested"
fi

replay="$("$REPLAY" "$work/journal.lcmlog")" || fail "the journal does not replay: $replay"
echo "$replay"
grep -q "bit-identical over [0-9]* ticks$" <<<"$replay" || fail "the replay: $replay"
echo "lcm.udpm_session: passed"
