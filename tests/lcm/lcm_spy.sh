#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# lcm.spy: scripts/lcm-spy under Xvfb, in a network namespace made here, watching a live
# enteron-lcm-server and the driver-side example over udpm. Passes when lcm-spy loads the
# types jar (it prints how many LCM types it found: all of bindings/lcm) and decodes the
# traffic for a few seconds without an exception. Exits 77 (ctest: skipped) with the reason
# when Java, lcm.jar, jchart2d.jar, Xvfb or a network namespace are missing
# (scripts/install-deps --with-lcm-java installs the Java pieces).
#   lcm_spy.sh WORK_DIR
# Environment: SERVER, DEVICE, SCENE, SPY (scripts/lcm-spy), BUILD (the build tree);
# SPY_SCREENSHOT=FILE.png also grabs the screen after a few seconds (needs ffmpeg).
set -euo pipefail
work="${1:?usage: lcm_spy.sh WORK_DIR}"
skip() { echo "lcm.spy: SKIPPED: $*"; exit 77; }
fail() { echo "lcm.spy: FAILED: $*" >&2; exit 1; }

if [[ "${ENTERON_IN_NAMESPACE:-}" != 1 ]]; then
  command -v java >/dev/null || skip "no Java runtime (scripts/install-deps --with-lcm-java)"
  [[ -f /usr/share/java/lcm.jar && -f /usr/share/java/jchart2d.jar ]] ||
    skip "no lcm.jar or jchart2d.jar (scripts/install-deps --with-lcm-java)"
  [[ -f "$BUILD/bindings/lcm/enteron_lcm_types.jar" ]] || skip "no types jar (no JDK when configured)"
  command -v Xvfb >/dev/null || skip "no Xvfb (Debian: xvfb)"
fi
source "$(dirname "${BASH_SOURCE[0]}")/network_namespace.sh"
enter_network_namespace lcm.spy "$@"
url='udpm://239.255.76.67:7667?ttl=0'
rm -rf "$work"
mkdir -p "$work"
cleanup() { jobs -p | xargs -r kill 2>/dev/null || true; }
trap cleanup EXIT

# Xvfb picks a free display and writes its number to fd 3.
Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>"$work/display" 2>"$work/xvfb.out" &
for _ in $(seq 100); do [[ -s "$work/display" ]] && break; sleep 0.05; done
[[ -s "$work/display" ]] || fail "Xvfb did not start: $(cat "$work/xvfb.out")"
export DISPLAY=":$(cat "$work/display")"

"$SERVER" --scene "$SCENE" --lcm-url "$url" --workspace-scale 0.001 --quiet >"$work/server.out" 2>&1 &
"$DEVICE" --lcm-url "$url" --seconds 8 --quiet >"$work/device.out" 2>&1 &
LCM_DEFAULT_URL="$url" "$SPY" --build "$BUILD" >"$work/spy.out" 2>&1 &
spy=$!
sleep 5
kill -0 "$spy" 2>/dev/null || { cat "$work/spy.out"; fail "lcm-spy exited early"; }
if [[ -n "${SPY_SCREENSHOT:-}" ]] && command -v ffmpeg >/dev/null; then
  ffmpeg -loglevel error -y -f x11grab -video_size 1280x800 -i "$DISPLAY" -frames:v 1 "$SPY_SCREENSHOT" &&
    echo "lcm.spy: screenshot in $SPY_SCREENSHOT"
fi
kill "$spy"
wait "$spy" 2>/dev/null || true
cat "$work/spy.out"
types="$(sed -n 's/^Found \([0-9]*\) LCM types$/\1/p' "$work/spy.out")"
expected="$(ls "$(dirname "$SPY")/../bindings/lcm/"*.lcm | wc -l)"
[[ -n "$types" && "$types" -ge "$expected" ]] || fail "lcm-spy found ${types:-no} LCM types, expected $expected"
if grep -Eq "Exception|Bad LCM Type|messageReceived ex" "$work/spy.out"; then fail "lcm-spy could not decode"; fi
echo "lcm.spy: lcm-spy found $types LCM types and decoded the session without an error: passed"
