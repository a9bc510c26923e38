#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Proves that abi/check bites: builds deliberately changed copies of libenteron.so and
# runs the real abi/check (with the committed baseline) on each.
#
#   removed_function  ent_effect_name is gone from lib/capi        -> must FAIL
#   inserted_field    a field inserted in the middle of ent_stats
#                     and of ent_scene_desc (the header)           -> must FAIL
#   appended_field    a field appended at the end of ent_stats:
#                     compatible thanks to struct_size            -> must PASS, for review
#
# One copy of the source tree and one build directory serve all three: the copy carries
# each change behind a preprocessor macro, and ENTERON_ABI_VARIANT (a compile definition
# of the enteron target only, added to the copy's lib/CMakeLists.txt) picks one, so each
# variant recompiles only lib/capi. Given CORE_ARCHIVE (the calling build's
# libenteron_core.a), the copy links it instead of compiling enteron_core again: abidw
# reads the types from lib/capi's debug information only, and those are the copy's.
#
# Usage: check_bites.sh SOURCE_DIR WORK_DIR [CORE_ARCHIVE]
# Environment: CMAKE (default cmake), NINJA (default: found by cmake), JOBS (default 2).
set -euo pipefail
source_dir="$(cd "${1:?usage: check_bites.sh SOURCE_DIR WORK_DIR}" && pwd)"
work_dir="${2:?usage: check_bites.sh SOURCE_DIR WORK_DIR}"
cmake_cmd="${CMAKE:-cmake}"
jobs="${JOBS:-2}"
ninja=()
[[ -n "${NINJA:-}" ]] && ninja=(-DCMAKE_MAKE_PROGRAM="$NINJA")
core_archive="${3:-}"
copy="$work_dir/src"
build="$work_dir/build"

fail() { printf 'check_bites: FAIL: %s\n' "$*" >&2; exit 1; }

mkdir -p "$work_dir"
rm -rf "$copy"
mkdir -p "$copy"
# Only what the library needs; -p keeps the times, so a rerun rebuilds only what changed.
cp -pr "$source_dir/CMakeLists.txt" "$source_dir/include" "$source_dir/lib" "$source_dir/cmake" "$copy/"

# Edits a file of the copy with a Python regex substitution that must match exactly once,
# keeping its time stamp (the edit is the same on every run). A pattern that no longer
# matches means the sources moved on: this test must then be updated, not skipped.
edit() {
    local file="$copy/$1" pattern="$2" replacement="$3"
    local stamp
    stamp="$(stat -c %Y "$file")"
    /usr/bin/python3 - "$file" "$pattern" "$replacement" <<'PY' || fail "cannot apply the change to $1 (update this test)"
import re, sys
path, pattern, replacement = sys.argv[1:4]
text = open(path).read()
changed, count = re.subn(pattern, replacement, text, flags=re.S | re.M)
if count != 1:
    sys.exit(f"pattern matched {count} times in {path}: {pattern!r}")
open(path, "w").write(changed)
PY
    touch -d "@$stamp" "$file"
}

edit lib/capi/status.cpp \
    '^(ENT_API const char\* ent_effect_name\(int32_t effect\) \{.*?^\}\n)' \
    '#if ENTERON_ABI_VARIANT != 1 /* removed_function */\n\1#endif\n'
edit include/enteron/enteron.h \
    '^(    double time_s; +/\*\*< simulated time\. \*/\n)' \
    '\1#if ENTERON_ABI_VARIANT == 2 /* inserted_field */\n    double inserted_by_abi_test;\n#endif\n'
edit include/enteron/enteron.h \
    '^(    double length_m; +/\*\*< rest length of the axis.*?\*/\n)' \
    '\1#if ENTERON_ABI_VARIANT == 2 /* inserted_field */\n    double inserted_by_abi_test;\n#endif\n'
edit include/enteron/enteron.h \
    '^(    uint64_t full_contact_searches; [^\n]*\n)' \
    '\1#if ENTERON_ABI_VARIANT == 3 /* appended_field */\n    double appended_by_abi_test;\n#endif\n'
edit lib/CMakeLists.txt \
    '^(target_compile_definitions\(enteron PRIVATE ENTERON_BUILDING_LIBRARY)\)' \
    '\1 ENTERON_ABI_VARIANT=${ENTERON_ABI_VARIANT})'
if [[ -n "$core_archive" ]]; then
    [[ -f "$core_archive" ]] || fail "no enteron_core archive at $core_archive"
    : >"$copy/lib/abi_prebuilt_core.cpp"
    edit lib/CMakeLists.txt \
        '^add_library\(enteron_core STATIC \$\{ENTERON_CORE_SOURCES\}\)$' \
        "add_library(enteron_core STATIC \${CMAKE_CURRENT_SOURCE_DIR}/abi_prebuilt_core.cpp)\ntarget_link_libraries(enteron_core PUBLIC $core_archive)"
fi

# Runs abi/check on the library built for one variant; prints its output; returns its status.
check_variant() {
    local number="$1" name="$2"
    printf '\n== variant %s (ENTERON_ABI_VARIANT=%s)\n' "$name" "$number"
    "$cmake_cmd" -S "$copy" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DENTERON_BUILD_TESTS=OFF -DENTERON_BUILD_EXAMPLES=OFF -DENTERON_BUILD_BENCH=OFF \
        -DENTERON_PYTHON_BINDING=OFF -DENTERON_CSHARP_BINDING=OFF -DENTERON_WITH_LCM=OFF \
        -DENTERON_ABI_VARIANT="$number" "${ninja[@]}" >"$work_dir/configure-$name.log" 2>&1 ||
        { cat "$work_dir/configure-$name.log"; fail "configuring the copy for $name failed"; }
    "$cmake_cmd" --build "$build" --target enteron --parallel "$jobs" >"$work_dir/build-$name.log" 2>&1 ||
        { cat "$work_dir/build-$name.log"; fail "building the copy for $name failed"; }
    set +e
    ENTERON_ABI_HEADERS="$copy/include" "$source_dir/abi/check" "$build/lib/libenteron.so" \
        >"$work_dir/check-$name.log" 2>&1
    local status=$?
    set -e
    cat "$work_dir/check-$name.log"
    return "$status"
}

# expect_failure NUMBER NAME TEXT...: abi/check must fail and its report must show each TEXT.
expect_failure() {
    local number="$1" name="$2"
    shift 2
    if check_variant "$number" "$name"; then fail "abi/check accepted the $name copy"; fi
    local text
    for text in "$@"; do
        grep -qF -- "$text" "$work_dir/check-$name.log" ||
            fail "abi/check failed on $name, but its report lacks: $text"
    done
    echo "check_bites: abi/check refused the $name copy, as it must"
}

expect_failure 1 removed_function "INCOMPATIBLE" "Removed function" "ent_effect_name"
expect_failure 2 inserted_field "INCOMPATIBLE" "struct ent_stats" "struct ent_scene_desc" \
    "inserted_by_abi_test" "offset changed"
check_variant 3 appended_field || fail "abi/check refused a field appended at the end of ent_stats"
grep -qF "appended_by_abi_test" "$work_dir/check-appended_field.log" ||
    fail "abi/check passed appended_field but did not print the change for review"
echo "check_bites: abi/check accepted the appended_field copy and printed it for review"

printf '\ncheck_bites: passed\n'
