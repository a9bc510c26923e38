#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks the ABI surface of libenteron.so: every defined dynamic symbol starts with ent_,
# every function the public header declares (ENT_API) is defined, and the SONAME is the
# expected one.
#
# Usage: check_exports.sh LIBRARY EXPECTED_SONAME [HEADER]
#   LIBRARY          path to the built libenteron.so (any of its names)
#   EXPECTED_SONAME  e.g. libenteron.so.0
#   HEADER           include/enteron/enteron.h; when given, each `ENT_API ... ent_x(` it
#                    declares must be a defined dynamic symbol of LIBRARY
# Environment: NM (default nm), READELF (default readelf).
set -euo pipefail
export LC_ALL=C

if [[ $# -lt 2 || $# -gt 3 ]]; then
  echo "usage: check_exports.sh LIBRARY EXPECTED_SONAME [HEADER]" >&2
  exit 2
fi
library="$1"
expected_soname="$2"
header="${3:-}"
nm_cmd="${NM:-nm}"
readelf_cmd="${READELF:-readelf}"
status=0

[[ -f "$library" ]] || { echo "FAIL: no library at $library" >&2; exit 1; }

# nm -D --defined-only prints "address type name"; a versioned name may carry @VERSION.
defined="$("$nm_cmd" -D --defined-only "$library" | awk 'NF >= 3 { sub(/@.*/, "", $3); print $3 }' | sort -u)"
count="$(grep -c . <<<"$defined" || true)"
echo "$count defined dynamic symbols in $library"

foreign="$(grep -v '^ent_' <<<"$defined" || true)"
if [[ -n "$foreign" ]]; then
  echo "FAIL: defined dynamic symbols that do not start with ent_:" >&2
  mapfile -t lines <<<"$foreign"
  printf '  %s\n' "${lines[@]}" >&2
  status=1
else
  echo "every defined dynamic symbol starts with ent_"
fi

if [[ -n "$header" ]]; then
  # Declarations may span lines: join the header, then pick the name before each "(".
  declared="$(tr '\n' ' ' <"$header" | grep -oE 'ENT_API[^;(]*\bent_[A-Za-z0-9_]+[[:space:]]*\(' |
    grep -oE 'ent_[A-Za-z0-9_]+[[:space:]]*\($' | tr -d ' (' | sort -u)"
  [[ -n "$declared" ]] || { echo "FAIL: found no ENT_API declaration in $header" >&2; exit 1; }
  missing="$(comm -23 <(echo "$declared") <(echo "$defined"))"
  if [[ -n "$missing" ]]; then
    echo "FAIL: declared in $(basename "$header") but not exported:" >&2
    mapfile -t lines <<<"$missing"
    printf '  %s\n' "${lines[@]}" >&2
    status=1
  else
    echo "all $(grep -c . <<<"$declared") ENT_API functions of $(basename "$header") are exported"
  fi
fi

soname="$("$readelf_cmd" -d "$library" | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')"
if [[ "$soname" != "$expected_soname" ]]; then
  echo "FAIL: SONAME is '${soname}', expected '${expected_soname}'" >&2
  status=1
else
  echo "SONAME is $soname"
fi

exit "$status"
