#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Checks that the unity builds compile what each file says (ENTERON_UNITY_BUILD).

    check_unity_names.py --root SOURCE_DIR

A unity build compiles a target's files together, one after the other in one translation
unit, so the anonymous namespaces of all its files (within one enclosing namespace) are one
namespace. Two files' private constants or types of one name collide: the compiler says so.
Two files' private functions of one name do not: they become one overload set, and a call
in the later file may quietly take the earlier file's function (a helper with other
parameters, converted arguments), or a file's private helper may hide a shared one (a
support header's) from the files after it. So no function defined at the top level of a
source file may share its name with one defined in another source file of the same target
within the same enclosing namespace, nor with one a header of the target defines, in any
namespace (a `using` brings those in), unless one is the other's declaration (a.h, a.cpp).

Python 3 standard library only. Prints one line per name and exits 1 if any.
"""
import argparse
import collections
import glob
import os
import re
import sys

# The files compiled together (a target's sources and the headers they share).
TARGETS = {
    "library": ["lib/base", "lib/numerics", "lib/spline", "lib/mechanics", "lib/collision", "lib/scene",
                "lib/skinning"],
    "C API": ["lib/capi"],
    "LCM bridge": ["lib/lcm"],
    "unit tests": ["tests/unit/*", "tests/support"],
    "C API tests": ["tests/capi", "tests/support"],
    "LCM tests": ["tests/lcm", "tests/lcm/*"],
    "stability tests": ["tests/stability"],
    "viewer": ["examples/viewer", "examples/viewer/remote"],
    "study": ["bench/study"],
}
# Files of which a build compiles only one.
ALTERNATIVES = [{"bench/study/peers_absent.cpp", "bench/study/peers_study.cpp"}]

KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "main", "decltype", "alignof", "static_assert"}
# A definition's first line at column 0: a return type, then name( with no ";" after it.
DEFINITION = re.compile(r"^(?:template\s*<[^>]*>\s*)?(?:(?:inline|static|constexpr)\s+)*"
                        r"(?:::)?[A-Za-z_][\w:<>,*&\s]*?[\s*&]([a-z_][a-z0-9_]*)\(([^;]*)$")
NAMESPACE = re.compile(r"^namespace ([\w:]+) \{")


def definitions(path):
    """(enclosing named namespace, function name) of each top-level definition in path."""
    found = []
    namespace = ""
    for line in open(path, encoding="utf-8"):
        opened = NAMESPACE.match(line)
        if opened:
            namespace = opened.group(1)
            continue
        match = DEFINITION.match(line)
        if match and match.group(1) not in KEYWORDS and not line.rstrip().endswith(";"):
            found.append((namespace, match.group(1)))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True)
    root = parser.parse_args().root
    problems = 0
    for target, folders in TARGETS.items():
        files = sorted({f for folder in folders for pattern in ("*.cpp", "*.h")
                        for f in glob.glob(os.path.join(root, folder, pattern))})
        where = collections.defaultdict(set)  # (namespace, name) -> sources
        in_headers = collections.defaultdict(set)  # name -> headers
        for path in files:
            for namespace, name in definitions(path):
                relative = os.path.relpath(path, root)
                if path.endswith(".h"):
                    in_headers[name].add(relative)
                else:
                    where[(namespace, name)].add(relative)
        for (namespace, name), sources in sorted(where.items()):
            paths = sources | in_headers.get(name, set())
            stems = {os.path.splitext(p)[0] for p in paths}
            if len(stems) < 2 or any(paths <= alternatives for alternatives in ALTERNATIVES):
                continue
            print(f"{target}: {namespace + '::' if namespace else ''}{name} is defined in "
                  f"{', '.join(sorted(paths))}: give each file's its own name")
            problems += 1
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
