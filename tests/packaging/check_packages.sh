#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks the Debian packages that cpack made (scripts/package, ctest packaging.debs), the
# way a user who installs them would meet them:
#   1. exactly the expected packages are there, one file each;
#   2. a package that holds a shared library is named after its SONAME (libfoo.so.0 ->
#      libfoo0, underscores become hyphens: Debian policy 8.1) and has a shlibs file;
#   3. dependencies: every package with a program or library depends on libc6 (what
#      dpkg-shlibdeps found), and on each of our packages whose library it needs, at
#      exactly this version;
#   4. each package unpacked with dpkg-deb -x into a scratch tree of its own together with
#      the packages of ours it depends on (and theirs), and nothing else: every program and
#      library there finds the libraries it needs; libenteron-dev's tree builds the C
#      consumer (tests/consumer) with find_package and with pkg-config, and it runs;
#      libenteron-lcm-dev's, when it is built, the bridge's consumer (tests/lcm/consumer);
#   5. lintian reports no error (its warnings and notes are printed, not fatal).
#
# Usage: check_packages.sh --packages DIR --work-dir DIR --expect "name name ..." [--no-lintian]
#   --packages  the directory holding the .deb files (and nothing else of ours)
#   --work-dir  scratch directory for this check; emptied first
#   --expect    the package names that must be there, and no others
# Environment: CMAKE, CC, PKG_CONFIG, CMAKE_GENERATOR, as tests/consumer/run_consumer_test.sh.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
packages_dir=""
work_dir=""
expected=()
run_lintian=1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --packages) packages_dir="$2"; shift 2 ;;
    --work-dir) work_dir="$2"; shift 2 ;;
    --expect) read -ra expected <<<"$2"; shift 2 ;;
    --no-lintian) run_lintian=0; shift ;;
    *) echo "check_packages.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [[ -z "$packages_dir" || -z "$work_dir" || ${#expected[@]} -eq 0 ]]; then
  echo "usage: check_packages.sh --packages DIR --work-dir DIR --expect \"name ...\" [--no-lintian]" >&2
  exit 2
fi

step() { printf '\n== %s\n' "$*"; }
fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }

rm -rf "$work_dir"
mkdir -p "$work_dir"
work_dir="$(cd "$work_dir" && pwd -P)"
packages_dir="$(cd "$packages_dir" && pwd -P)"

step "1. the packages in $packages_dir"
declare -A deb_of=()  # package name -> .deb file
shopt -s nullglob
debs=("$packages_dir"/*.deb)
shopt -u nullglob
[[ ${#debs[@]} -gt 0 ]] || fail "no .deb file in $packages_dir"
for deb in "${debs[@]}"; do
  name="$(dpkg-deb -f "$deb" Package)"
  [[ -z "${deb_of[$name]:-}" ]] || fail "two files for package $name: ${deb_of[$name]} and $deb"
  deb_of[$name]="$deb"
  printf '%-22s %8s bytes  %s\n' "$name" "$(stat -c %s "$deb")" "$(basename "$deb")"
done
for name in "${expected[@]}"; do
  [[ -n "${deb_of[$name]:-}" ]] || fail "package $name is missing"
done
[[ ${#deb_of[@]} -eq ${#expected[@]} ]] ||
  fail "found packages ${!deb_of[*]}, expected exactly ${expected[*]}"
version="$(dpkg-deb -f "${deb_of[${expected[0]}]}" Version)"
for name in "${expected[@]}"; do
  [[ "$(dpkg-deb -f "${deb_of[$name]}" Version)" == "$version" ]] ||
    fail "$name has version $(dpkg-deb -f "${deb_of[$name]}" Version), ${expected[0]} has $version"
done
echo "all at version $version"

# Unpack each package on its own, to see what it holds.
for name in "${expected[@]}"; do
  mkdir -p "$work_dir/one/$name" "$work_dir/control/$name"
  dpkg-deb -x "${deb_of[$name]}" "$work_dir/one/$name"
  dpkg-deb -e "${deb_of[$name]}" "$work_dir/control/$name"
done

# The development package carries both public headers: the C ABI and the C++ layer over it.
for header in enteron.h enteron.hpp; do
  [[ -f "$work_dir/one/libenteron-dev/usr/include/enteron/$header" ]] ||
    fail "libenteron-dev does not hold usr/include/enteron/$header"
done

# The ELF files a package holds (programs and shared libraries, not symlinks).
elf_files() {
  local file
  while IFS= read -r -d '' file; do
    [[ "$(head -c 4 "$file" | od -An -c | tr -d ' ')" == '177ELF' ]] && printf '%s\n' "$file"
  done < <(find "$work_dir/one/$1" -type f -print0)
  return 0
}
soname_of() { readelf -d "$1" | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p'; }
# libfoo_bar.so.0 -> libfoo-bar0; libfoo2.so.1 -> libfoo2-1 (a hyphen between two digits).
package_for_soname() {
  local base="${1%%.so.*}" major="${1##*.so.}"
  base="${base//_/-}"
  if [[ "$base" =~ [0-9]$ ]]; then printf '%s-%s\n' "$base" "$major"; else printf '%s%s\n' "$base" "$major"; fi
}

step "2. library packages are named after their SONAME and carry a shlibs file"
declare -A package_of_soname=()
for name in "${expected[@]}"; do
  while IFS= read -r file; do
    soname="$(soname_of "$file")"
    [[ -n "$soname" && "$file" == *.so.* ]] || continue
    want="$(package_for_soname "$soname")"
    [[ "$name" == "$want" ]] || fail "$name holds $(basename "$file") (SONAME $soname): the package must be named $want"
    grep -qE "^${soname%%.so.*} ${soname##*.so.} $name " "$work_dir/control/$name/shlibs" ||
      fail "$name: its shlibs file does not declare $soname"
    package_of_soname[$soname]="$name"
    echo "$name: $soname, shlibs: $(cat "$work_dir/control/$name/shlibs")"
  done < <(elf_files "$name")
done
[[ ${#package_of_soname[@]} -gt 0 ]] || fail "no package holds a shared library"

step "3. dependencies"
for name in "${expected[@]}"; do
  depends="$(dpkg-deb -f "${deb_of[$name]}" Depends)"
  echo "$name: Depends: $depends"
  mapfile -t files < <(elf_files "$name")
  if [[ ${#files[@]} -gt 0 ]]; then
    [[ ", $depends," == *", libc6 (>= "* ]] || fail "$name holds ELF files but does not depend on libc6: dpkg-shlibdeps did not run"
  fi
  for file in "${files[@]}"; do
    while IFS= read -r needed; do
      provider="${package_of_soname[$needed]:-}"
      [[ -n "$provider" && "$provider" != "$name" ]] || continue
      [[ ", $depends," == *", $provider (= $version),"* ]] ||
        fail "$name: $(basename "$file") needs $needed, but $name does not depend on $provider (= $version)"
    done < <(readelf -d "$file" | sed -n 's/.*(NEEDED).*\[\(.*\)\].*/\1/p')
  done
done
# A development package holds no library of its own but leads to one: it depends on it.
for name in "${expected[@]}"; do
  [[ "$name" == *-dev ]] || continue
  while IFS= read -r link; do
    target="$(basename "$(readlink "$link")")"  # libfoo.so.0 or libfoo.so.0.1.0
    for provided in "${!package_of_soname[@]}"; do
      [[ "$target" == "$provided" || "$target" == "$provided".* ]] || continue
      provider="${package_of_soname[$provided]}"
      [[ ", $(dpkg-deb -f "${deb_of[$name]}" Depends)," == *", $provider (= $version),"* ]] ||
        fail "$name holds $(basename "$link") -> $target but does not depend on $provider (= $version)"
      echo "$name: $(basename "$link") -> $target, from $provider"
    done
  done < <(find "$work_dir/one/$name" -type l -name '*.so')
done

step "4. each package with the packages of ours it depends on, unpacked in a tree of its own"
# unpack_closure NAME TREE: NAME and, recursively, every package of ours in its Depends.
unpack_closure() {
  local name="$1" tree="$2" dependency
  [[ ! -e "$tree/.unpacked-$name" ]] || return 0
  dpkg-deb -x "${deb_of[$name]}" "$tree"
  touch "$tree/.unpacked-$name"
  while IFS= read -r dependency; do
    dependency="${dependency%% *}"
    [[ -z "${deb_of[$dependency]:-}" ]] || unpack_closure "$dependency" "$tree"
  done < <(dpkg-deb -f "${deb_of[$name]}" Depends | tr ',' '\n' | sed 's/^ *//')
}
libdir=""
for name in "${expected[@]}"; do
  tree="$work_dir/tree/$name"
  mkdir -p "$tree"
  unpack_closure "$name" "$tree"
  echo "$name: $(cd "$tree" && ls .unpacked-* | sed 's/^\.unpacked-//' | tr '\n' ' ')"
  # Where our libraries are in this tree (the multiarch libdir, or lib).
  library_dirs="$(find "$tree/usr" -name 'libenteron*.so.*' -printf '%h\n' | sort -u | paste -sd:)"
  while IFS= read -r file; do
    missing="$(LD_LIBRARY_PATH="$library_dirs" ldd "$file" | grep 'not found' || true)"
    [[ -z "$missing" ]] || fail "$name: ${file#"$work_dir/one/$name"} with only $name and the packages it depends on: $missing"
  done < <(elf_files "$name")
  pc_file="$(find "$tree/usr" -path '*/pkgconfig/enteron.pc' -print -quit)"
  if [[ -n "$pc_file" && -z "$libdir" ]]; then
    libdir="${pc_file#"$tree/usr/"}"
    libdir="${libdir%/pkgconfig/enteron.pc}"
  fi
done
echo "every program and library finds the libraries it needs; libdir: $libdir"
[[ -n "${deb_of[libenteron-dev]:-}" ]] || fail "no libenteron-dev to build the consumer with"
"$here/../consumer/run_consumer_test.sh" --installed-tree "$work_dir/tree/libenteron-dev/usr" \
  --work-dir "$work_dir/consumer" --mode all --libdir "$libdir" --includedir include

if [[ -n "${deb_of[libenteron-lcm-dev]:-}" ]]; then
  step "4b. the LCM bridge's consumer against libenteron-lcm-dev's tree"
  prefix="$work_dir/tree/libenteron-lcm-dev/usr"
  lcm_consumer="$here/../lcm/consumer"
  "${CMAKE:-cmake}" -S "$lcm_consumer" -B "$work_dir/lcm-consumer" -DCMAKE_PREFIX_PATH="$prefix"
  "${CMAKE:-cmake}" --build "$work_dir/lcm-consumer"
  LD_LIBRARY_PATH="$prefix/$libdir" "$work_dir/lcm-consumer/lcm_consumer"
  read -ra flags <<<"$(PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig" "${PKG_CONFIG:-pkg-config}" --cflags --libs enteron_lcm)"
  echo "pkg-config enteron_lcm: ${flags[*]}"
  "${CC:-cc}" -std=c99 -pedantic -Wall -Wextra -Werror "$lcm_consumer/lcm_consumer.c" \
    -o "$work_dir/lcm-consumer-pkg-config" "${flags[@]}" -Wl,-rpath,"$prefix/$libdir"
  "$work_dir/lcm-consumer-pkg-config"
fi

if [[ $run_lintian -eq 1 ]]; then
  step "5. lintian"
  command -v lintian >/dev/null || fail "lintian is not installed (scripts/install-deps installs it)"
  status=0
  lintian --fail-on error --display-level '>=info' "${debs[@]}" >"$work_dir/lintian.log" 2>&1 || status=$?
  cat "$work_dir/lintian.log"
  errors="$(grep -c '^E: ' "$work_dir/lintian.log" || true)"
  echo "lintian: $errors error(s), $(grep -c '^W: ' "$work_dir/lintian.log" || true) warning(s), exit status $status"
  [[ $status -eq 0 && $errors -eq 0 ]] || fail "lintian reports errors"
fi

printf '\npackages checked: %s\n' "${expected[*]}"
