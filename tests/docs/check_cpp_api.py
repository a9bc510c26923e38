#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Checks that the C++ layer covers the C API.

    check_cpp_api.py --root SOURCE_DIR

Every function include/enteron/enteron.h exports (declared with ENT_API) must be called by
include/enteron/enteron.hpp (in its code, not in a comment), directly or through a macro
of enteron.h that calls it (ent_scene_desc_default calls ent_scene_desc_init), or be
listed in docs/cpp.md's table "C functions without a C++ counterpart" with a reason; and
docs/cpp.md's table "Every C function and its counterpart" must name it. Fails (one line
per problem) otherwise, and when docs/cpp.md names a function the header does not export.

Python 3 standard library only.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_docs import Problems, read  # noqa: E402  (the same report as the other docs checks)


def without_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def exported(header):
    return set(re.findall(r"^ENT_API\s[^;(]*?\b(ent_[a-z0-9_]+)\s*\(", header, flags=re.M))


def macros_calling(header):
    """Macro name -> the ent_ functions its body calls."""
    calls = {}
    for match in re.finditer(r"^#define\s+(ent_[a-z0-9_]+)\s*\([^)]*\)((?:[^\n]*\\\n)*[^\n]*)", header, flags=re.M):
        calls[match.group(1)] = set(re.findall(r"\b(ent_[a-z0-9_]+)\s*\(", match.group(2)))
    return calls


def table_rows(markdown, heading):
    """The first column's function names of the table under `heading`."""
    at = markdown.find(heading)
    if at < 0:
        return None
    names = set()
    for line in markdown[at:].splitlines()[1:]:
        if line.startswith("#"):
            break
        if line.startswith("|") and not line.startswith("|---"):
            first = line.split("|")[1]
            names.update(re.findall(r"`(ent_[a-z0-9_]+)`", first))
    return names


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", required=True)
    root = parser.parse_args().root
    header = read(os.path.join(root, "include", "enteron", "enteron.h"))
    cpp = without_comments(read(os.path.join(root, "include", "enteron", "enteron.hpp")))
    manual = read(os.path.join(root, "docs", "cpp.md"))
    functions = exported(header)
    called = set(re.findall(r"\b(ent_[a-z0-9_]+)\s*\(", cpp))
    for macro, inner in macros_calling(header).items():
        if macro in called:
            called |= inner
    listed = table_rows(manual, "## Every C function and its counterpart")
    excused = table_rows(manual, "## C functions without a C++ counterpart")
    problems = Problems()
    if listed is None or excused is None:
        problems.add("docs/cpp.md lacks the section \"Every C function and its counterpart\" or "
                     "\"C functions without a C++ counterpart\"")
        listed, excused = listed or set(), excused or set()
    for name in sorted(functions - called - excused):
        problems.add(f"{name} (include/enteron/enteron.h) has no counterpart in include/enteron/enteron.hpp "
                     "and no reason in docs/cpp.md")
    for name in sorted(excused & called):
        problems.add(f"docs/cpp.md says {name} has no C++ counterpart, but enteron.hpp calls it")
    for name in sorted(functions - listed - excused):
        problems.add(f"docs/cpp.md's table does not name {name}")
    for name in sorted((listed | excused) - functions):
        problems.add(f"docs/cpp.md names {name}, which include/enteron/enteron.h does not export")
    return problems.report(f"all {len(functions)} exported C functions have their C++ counterpart "
                          f"({len(excused)} excused in docs/cpp.md)")


if __name__ == "__main__":
    sys.exit(main())
