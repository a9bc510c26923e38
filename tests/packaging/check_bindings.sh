#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the bindings' Debian packages into a scratch root and uses them as a user who
# ran `apt install python3-enteron libenteron-cil` would (ctest packaging.bindings, after
# packaging.debs; scripts/package):
#   1. python3-enteron, libenteron-cil and libenteron0 (what they depend on of ours) are
#      unpacked into a scratch root; what else they depend on must be installed here;
#   2. in a mount namespace of its own, that root's /usr is laid over the system's /usr
#      (a read-only overlay: nothing of the system changes, and the packages' files sit
#      exactly where apt would put them);
#   3. there, with PYTHONPATH unset, python3 imports enteron from
#      /usr/lib/python3/dist-packages, loads the packaged library and runs the minimal
#      example; mcs compiles examples/csharp/Minimal.cs with -pkg:enteron-sharp and mono
#      runs it with MONO_PATH=/usr/lib/cli/enteron, and again with Enteron.dll copied beside
#      it; both print the minimal example's line.
# Exits 77 (ctest: skipped) where a mount namespace cannot be made (unshare -m needs root).
#
# Usage: check_bindings.sh --packages DIR --work-dir DIR
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source_dir="$(cd "$here/../.." && pwd)"
packages_dir=""
work_dir=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --packages) packages_dir="$2"; shift 2 ;;
    --work-dir) work_dir="$2"; shift 2 ;;
    --inside) shift; inside=1 ;;
    *) echo "check_bindings.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[[ -n "$packages_dir" && -n "$work_dir" ]] || { echo "usage: check_bindings.sh --packages DIR --work-dir DIR" >&2; exit 2; }
step() { printf '\n== %s\n' "$*"; }
fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }
root="$work_dir/root"

if [[ -z "${inside:-}" ]]; then
  step "1. python3-enteron, libenteron-cil and libenteron0 into the scratch root $root"
  rm -rf "$work_dir"
  mkdir -p "$root"
  for name in libenteron0 python3-enteron libenteron-cil; do
    deb="$(ls "$packages_dir"/${name}_*.deb 2>/dev/null | head -n 1)"
    [[ -n "$deb" ]] || fail "no ${name}_*.deb in $packages_dir"
    dpkg-deb -x "$deb" "$root"
    depends="$(dpkg-deb -f "$deb" Depends)"
    echo "$name ($(dpkg-deb -f "$deb" Architecture)): Depends: $depends"
    while IFS= read -r dependency; do
      dependency="${dependency%% *}"
      [[ -z "$dependency" || "$dependency" == libenteron0 ]] && continue
      [[ "$(dpkg-query -W -f='${Status}' "$dependency" 2>/dev/null || true)" == "install ok installed" ]] ||
        fail "$name depends on $dependency, which is not installed here (scripts/install-deps)"
    done < <(tr ',' '\n' <<<"$depends" | sed 's/^ *//')
  done
  [[ -f "$root/usr/lib/python3/dist-packages/enteron/__init__.py" ]] || fail "python3-enteron holds no /usr/lib/python3/dist-packages/enteron"
  [[ -f "$root/usr/lib/cli/enteron/Enteron.dll" ]] || fail "libenteron-cil holds no /usr/lib/cli/enteron/Enteron.dll"

  step "2. the root laid over /usr in a mount namespace of its own"
  if ! unshare -m true 2>/dev/null; then
    echo "check_bindings.sh: SKIPPED: cannot make a mount namespace here (unshare -m needs root or CAP_SYS_ADMIN)"
    exit 77
  fi
  exec unshare -m "$0" --packages "$packages_dir" --work-dir "$work_dir" --inside
fi

mount --make-rprivate /  # nothing mounted here reaches the system's namespace
mount -t overlay enteron-packages -o "lowerdir=$root/usr:/usr" /usr
library="$(find /usr/lib -maxdepth 2 -name 'libenteron.so.0' -print -quit)"
[[ -n "$library" ]] || fail "no libenteron.so.0 under /usr/lib with the packages laid over it"
cmp -s "$library" "$root/${library#/}" || fail "$library is not the packaged library"
echo "the packaged files are in /usr: $library, /usr/lib/python3/dist-packages/enteron, /usr/lib/cli/enteron"

step "3a. import enteron, with no PYTHONPATH"
cd "$work_dir"
env -u PYTHONPATH -u ENTERON_LIBRARY /usr/bin/python3 - "$library" <<'PY'
import os, sys
import enteron
library = sys.argv[1]
where = os.path.dirname(enteron.__file__)
assert where == "/usr/lib/python3/dist-packages/enteron", "enteron imported from %s" % where
assert os.path.realpath(enteron.library_path) == os.path.realpath(library), \
    "enteron loaded %s, not %s" % (enteron.library_path, library)
print("python3: enteron %s from %s, libenteron %s" % (enteron.version, where, enteron.library_path))
PY
line="$(env -u PYTHONPATH -u ENTERON_LIBRARY /usr/bin/python3 "$source_dir/examples/python/minimal.py")"
echo "$line"
[[ "$line" == "minimal.py: libenteron "*", t = 1.000 s, 100 axis points"* ]] || fail "the Python minimal example printed: $line"

step "3b. Enteron.dll: mcs -pkg:enteron-sharp, then mono"
mkdir -p csharp copied
mcs -pkg:enteron-sharp -out:csharp/Minimal.exe "$source_dir/examples/csharp/Minimal.cs"
line="$(MONO_PATH=/usr/lib/cli/enteron mono csharp/Minimal.exe)"
echo "MONO_PATH=/usr/lib/cli/enteron: $line"
[[ "$line" == "minimal: t = 1.000 s, 100 axis points"* ]] || fail "the C# minimal example printed: $line"
cp csharp/Minimal.exe /usr/lib/cli/enteron/Enteron.dll /usr/lib/cli/enteron/Enteron.dll.config copied/
line="$(env -u MONO_PATH -u LD_LIBRARY_PATH mono copied/Minimal.exe)"
echo "Enteron.dll copied beside the program: $line"
[[ "$line" == "minimal: t = 1.000 s, 100 axis points"* ]] || fail "the C# minimal example with a copied Enteron.dll printed: $line"

printf '\nbindings checked: python3-enteron and libenteron-cil installed and used\n'
