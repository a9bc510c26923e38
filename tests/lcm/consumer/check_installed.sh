#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# lcm.installed: cmake --install puts the bridge where a user finds it (library, header,
# CMake package component, enteron_lcm.pc, the two programs, the .lcm types and the Python
# reader), and a C program builds and runs against it both through find_package and
# through pkg-config.
#   check_installed.sh BUILD_DIR WORK_DIR LIBDIR BINDIR DATADIR
# Environment: CMAKE, CC, CMAKE_GENERATOR.
set -euo pipefail
build="$1" work="$2" libdir="$3" bindir="$4" datadir="$5"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cmake_cmd="${CMAKE:-cmake}"
fail() { echo "lcm.installed: FAILED: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
stage="$work/stage"
"$cmake_cmd" --install "$build" --prefix "$stage" >"$work/install.log" || { cat "$work/install.log"; fail "install"; }
for file in "$libdir/libenteron_lcm.so" "$libdir/libenteron_lcm.so.0" include/enteron/enteron_lcm.h \
            "$libdir/pkgconfig/enteron_lcm.pc" "$bindir/enteron-lcm-server" "$bindir/enteron-lcm-replay" \
            "$datadir/enteron/lcm/tool_command_t.lcm" "$datadir/enteron/lcm/tool_feedback_t.lcm"; do
  [[ -e "$stage/$file" ]] || fail "missing $file"
done
types="$(ls "$stage/$datadir/enteron/lcm/"*.lcm | wc -l)"
[[ "$types" -eq "$(ls "$here/../../../bindings/lcm/"*.lcm | wc -l)" ]] || fail "$types .lcm files installed"
python_reader="$(find "$stage" -path '*enteron_lcm/log.py' | head -n 1)"
[[ -n "$python_reader" && -f "$(dirname "$python_reader")/enteron/tool_feedback_t.py" ]] ||
  fail "the Python reader and its generated types are not installed"
"$stage/$bindir/enteron-lcm-server" --help | grep -q -- "--scene FILE.json" || fail "the installed server"
echo "layout ok: library, header, enteron_lcm.pc, programs, $types .lcm types, Python reader"

"$cmake_cmd" -S "$here" -B "$work/cmake" -DCMAKE_PREFIX_PATH="$stage" >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; fail "find_package(enteron COMPONENTS lcm)"; }
"$cmake_cmd" --build "$work/cmake" >"$work/build.log" 2>&1 || { cat "$work/build.log"; fail "building the consumer"; }
LD_LIBRARY_PATH="$stage/$libdir" "$work/cmake/lcm_consumer" || fail "the CMake consumer"

pc_path="$stage/$libdir/pkgconfig"
read -ra flags <<<"$(PKG_CONFIG_PATH="$pc_path" pkg-config --cflags --libs enteron_lcm)"
"${CC:-cc}" -std=c99 -pedantic -Wall -Wextra -Werror "$here/lcm_consumer.c" -o "$work/pkg_config_consumer" \
  "${flags[@]}" -Wl,-rpath,"$stage/$libdir"
"$work/pkg_config_consumer" || fail "the pkg-config consumer"
echo "lcm.installed: passed"
