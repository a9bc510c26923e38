#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs an already-built Enteron into a staging prefix and builds a small C consumer
# against it, the way a user outside the project would, then moves the staged tree and
# does it again to prove that the installed package is relocatable.
#
# Usage: run_consumer_test.sh (--build-dir DIR | --installed-tree DIR) --work-dir DIR
#                             [--mode cmake|pkg-config|all] [--libdir lib] [--includedir include]
#   --build-dir   the configured and built Enteron build tree (cmake --install reads it)
#   --installed-tree  an already installed prefix (e.g. the usr/ of unpacked Debian
#                 packages, tests/packaging): copied, not installed; left as it is
#   --work-dir    scratch directory for this test; emptied first
#   --mode        cmake: find_package(enteron CONFIG) project in this folder;
#                 pkg-config: cc $(pkg-config --cflags --libs enteron); all: both (default)
#   --libdir, --includedir: CMAKE_INSTALL_LIBDIR / CMAKE_INSTALL_INCLUDEDIR of that build
# Environment: CMAKE (default cmake), CMAKE_GENERATOR (passed through to cmake),
#              CC (default cc), PKG_CONFIG (default pkg-config).
# Paths containing spaces are not supported (pkg-config output is split on whitespace).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build_dir=""
installed_tree=""
work_dir=""
mode="all"
libdir="lib"
includedir="include"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build-dir) build_dir="$2"; shift 2 ;;
    --installed-tree) installed_tree="$2"; shift 2 ;;
    --work-dir) work_dir="$2"; shift 2 ;;
    --mode) mode="$2"; shift 2 ;;
    --libdir) libdir="$2"; shift 2 ;;
    --includedir) includedir="$2"; shift 2 ;;
    *) echo "run_consumer_test.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [[ -z "$build_dir" && -z "$installed_tree" || -n "$build_dir" && -n "$installed_tree" || -z "$work_dir" ]]; then
  echo "usage: run_consumer_test.sh (--build-dir DIR | --installed-tree DIR) --work-dir DIR [--mode cmake|pkg-config|all]" >&2
  exit 2
fi
case "$mode" in
  cmake | pkg-config | all) ;;
  *) echo "run_consumer_test.sh: --mode must be cmake, pkg-config or all, got '$mode'" >&2; exit 2 ;;
esac

cmake_cmd="${CMAKE:-cmake}"
cc_cmd="${CC:-cc}"
pkg_config_cmd="${PKG_CONFIG:-pkg-config}"

step() { printf '\n== %s\n' "$*"; }
fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }

rm -rf "$work_dir"
mkdir -p "$work_dir"
work_dir="$(cd "$work_dir" && pwd -P)"
stage="$work_dir/stage"
moved="$work_dir/moved/somewhere/else"

if [[ -n "$installed_tree" ]]; then
  step "copy the installed tree $installed_tree to $stage"
  cp -a "$installed_tree" "$stage"
else
  build_dir="$(cd "$build_dir" && pwd -P)"
  step "install $build_dir into $stage"
  "$cmake_cmd" --install "$build_dir" --prefix "$stage"
fi

step "check the installed layout"
check_layout() {
  local prefix="$1"
  local lib="$prefix/$libdir"
  [[ -f "$prefix/$includedir/enteron/enteron.h" ]] || fail "missing $includedir/enteron/enteron.h"
  [[ -L "$lib/libenteron.so" ]] || fail "$libdir/libenteron.so is not a symlink (namelink)"
  local soname_links=("$lib"/libenteron.so.[0-9]*)
  local real_file=""
  local soname_link=""
  local f
  for f in "${soname_links[@]}"; do
    [[ -e "$f" ]] || continue
    if [[ -L "$f" ]]; then soname_link="$f"; else real_file="$f"; fi
  done
  [[ -n "$soname_link" ]] || fail "no SONAME symlink libenteron.so.<major> in $libdir"
  [[ -n "$real_file" ]] || fail "no versioned libenteron.so.<version> file in $libdir"
  [[ "$(readlink -f "$lib/libenteron.so")" == "$(readlink -f "$real_file")" ]] ||
    fail "libenteron.so does not lead to $real_file"
  [[ "$(readlink -f "$soname_link")" == "$(readlink -f "$real_file")" ]] ||
    fail "$soname_link does not lead to $real_file"
  local file
  for file in enteronConfig.cmake enteronConfigVersion.cmake enteronTargets.cmake; do
    [[ -f "$lib/cmake/enteron/$file" ]] || fail "missing $libdir/cmake/enteron/$file"
  done
  [[ -f "$lib/pkgconfig/enteron.pc" ]] || fail "missing $libdir/pkgconfig/enteron.pc"
  echo "layout ok: $(basename "$real_file"), $(basename "$soname_link") -> $(readlink "$soname_link"), libenteron.so -> $(readlink "$lib/libenteron.so")"
}
check_layout "$stage"

# Nothing installed may point back at the place it was installed to.
if grep -rlF "$stage" "$stage/$libdir/pkgconfig" "$stage/$libdir/cmake"; then
  fail "the files above contain the absolute install path $stage: not relocatable"
fi
echo "no absolute install path in the .pc and CMake package files"

version="$(sed -n 's/^set(PACKAGE_VERSION "\([^"]*\)")$/\1/p' \
  "$stage/$libdir/cmake/enteron/enteronConfigVersion.cmake")"
[[ -n "$version" ]] || fail "cannot read PACKAGE_VERSION from enteronConfigVersion.cmake"
major="${version%%.*}"
echo "package version $version"

# Runs a consumer executable and checks that it loaded libenteron from the given prefix.
run_consumer() {
  local exe="$1" prefix="$2"
  local loaded
  loaded="$(ldd "$exe" | awk '$1 ~ /^libenteron\.so/ { print $3 }')"
  [[ -n "$loaded" && "$(readlink -f "$(dirname "$loaded")")" == "$(readlink -f "$prefix/$libdir")" ]] ||
    fail "$exe loads libenteron from '$loaded', expected it from $prefix/$libdir"
  echo "$exe loads $loaded"
  "$exe" || fail "$exe exited with status $?"
}

consume_with_cmake() {
  local prefix="$1" tag="$2"
  local bin="$work_dir/consumer-cmake-$tag"
  step "CMake consumer against $prefix: find_package(enteron $version CONFIG REQUIRED)"
  local log="$work_dir/configure-$tag.log"
  if ! "$cmake_cmd" -S "$here" -B "$bin" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" -DENTERON_CONSUMER_VERSION="$version" >"$log" 2>&1; then
    cat "$log"
    fail "configuring the consumer project failed"
  fi
  cat "$log"
  grep -qF "from $prefix/$libdir/cmake/enteron" "$log" ||
    fail "find_package did not take enteron from $prefix"
  "$cmake_cmd" --build "$bin"
  run_consumer "$bin/consumer" "$prefix"

  local next_major=$((major + 1))
  step "CMake consumer asking for enteron $next_major.0 must be refused (SameMajorVersion)"
  local refused="$work_dir/consumer-cmake-$tag-next-major"
  if "$cmake_cmd" -S "$here" -B "$refused" -DCMAKE_PREFIX_PATH="$prefix" \
      -DENTERON_CONSUMER_VERSION="$next_major.0" >"$log" 2>&1; then
    cat "$log"
    fail "find_package(enteron $next_major.0) accepted version $version"
  fi
  grep -q "compatible with requested version" "$log" || {
    cat "$log"
    fail "configuring for enteron $next_major.0 failed, but not on the version check"
  }
  echo "refused as expected"
}

consume_with_pkg_config() {
  local prefix="$1" tag="$2"
  local pc_path="$prefix/$libdir/pkgconfig"
  step "pkg-config consumer against $prefix (PKG_CONFIG_PATH=$pc_path)"
  local pc_version pc_libdir cflags libs
  pc_version="$(PKG_CONFIG_PATH="$pc_path" "$pkg_config_cmd" --modversion enteron)"
  [[ "$pc_version" == "$version" ]] || fail "pkg-config says version $pc_version, expected $version"
  pc_libdir="$(PKG_CONFIG_PATH="$pc_path" "$pkg_config_cmd" --variable=libdir enteron)"
  [[ "$(cd "$pc_libdir" && pwd -P)" == "$(cd "$prefix/$libdir" && pwd -P)" ]] ||
    fail "pkg-config libdir '$pc_libdir' is not $prefix/$libdir"
  read -ra cflags <<<"$(PKG_CONFIG_PATH="$pc_path" "$pkg_config_cmd" --cflags enteron)"
  read -ra libs <<<"$(PKG_CONFIG_PATH="$pc_path" "$pkg_config_cmd" --libs enteron)"
  echo "cflags: ${cflags[*]}"
  echo "libs:   ${libs[*]}"
  local exe="$work_dir/consumer-pkg-config-$tag"
  "$cc_cmd" -std=c99 -pedantic -Wall -Wextra -Werror "${cflags[@]}" "$here/consumer.c" \
    -o "$exe" "${libs[@]}" -lm -Wl,-rpath,"$pc_libdir"
  run_consumer "$exe" "$prefix"
}

consume() {
  local prefix="$1" tag="$2"
  if [[ "$mode" == cmake || "$mode" == all ]]; then consume_with_cmake "$prefix" "$tag"; fi
  if [[ "$mode" == pkg-config || "$mode" == all ]]; then consume_with_pkg_config "$prefix" "$tag"; fi
}

consume "$stage" staged

step "move the installed tree to $moved and consume it there"
mkdir -p "$(dirname "$moved")"
mv "$stage" "$moved"
check_layout "$moved"
consume "$moved" moved

printf '\nconsumer test (%s) passed\n' "$mode"
