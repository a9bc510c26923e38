#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What each candidate library for organ meshes would add to libenteron.so's run-time
# dependencies (docs/anatomy.md, bench/results/anatomy_libraries.md): its DT_NEEDED entries,
# and the shared objects it loads (itself and ldd's closure) that a C++ library loads anyway
# (libstdc++ and its own closure), with their total size on disk. CGAL is header-only: it adds
# none. Run:
#   bench/anatomy_library_footprint.sh
set -euo pipefail
dir=/usr/lib/x86_64-linux-gnu
closure() { (readlink -f "$1"; ldd "$1" | awk '/=>/ {print $3}' | xargs -n1 readlink -f) | sort -u; }
base=$(closure "$dir/libstdc++.so.6")
echo "| library | DT_NEEDED | shared objects added | MiB added on disk |"
echo "|---|---|---:|---:|"
for candidate in libembree3.so.3 libopenvdb.so.10.0 libtinyobjloader.so.2rc10 libassimp.so.5; do
  path=$dir/$candidate
  if [[ ! -e $path ]]; then
    echo "| $candidate | not installed | | |"
    continue
  fi
  needed=$(readelf -d "$path" | awk '/NEEDED/ {gsub(/[][]/, "", $5); print $5}' | paste -sd' ')
  added=$(comm -23 <(closure "$path") <(echo "$base"))
  count=$(grep -c . <<<"$added" || true)
  bytes=$(xargs -r stat -L -c %s <<<"$added" | paste -sd+ | bc)
  printf '| %s | %s | %d | %.1f |\n' "$candidate" "$needed" "$count" "$(bc -l <<<"${bytes:-0} / 1048576")"
done
