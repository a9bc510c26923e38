#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Checks that every unit of the library has its unit test file or a stated reason.

    check_unit_tests.py --root SOURCE_DIR

A unit is lib/<layer>/<name>.h and/or <name>.cpp, for the layers base, numerics, spline,
mechanics, collision, scene, skinning and capi. Its test file is
tests/unit/<layer>/test_<name>.cpp. tests/unit/README.md lists, in its table "Units without
a test file of their own", each unit that has none and why. Fails (one line per problem)
when a unit has neither, when a row names a unit that does not exist or that has a test
file now, or when a row's reason names a tests/ file that does not exist.

Python 3 standard library only.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_docs import Problems  # noqa: E402  (the same report as the other docs checks)

LAYERS = ["base", "numerics", "spline", "mechanics", "collision", "scene", "skinning", "capi"]


def units(root):
    found = set()
    for layer in LAYERS:
        for name in os.listdir(os.path.join(root, "lib", layer)):
            stem, extension = os.path.splitext(name)
            if extension in (".h", ".cpp"):
                found.add(f"{layer}/{stem}")
    return found


def listed(root):
    """The README's rows: unit -> reason."""
    rows = {}
    with open(os.path.join(root, "tests", "unit", "README.md"), encoding="utf-8") as f:
        for line in f:
            match = re.match(r"^\| `([a-z_]+/[a-z0-9_]+)` \| (.*) \|\s*$", line)
            if match:
                rows[match.group(1)] = match.group(2)
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", required=True)
    root = parser.parse_args().root
    problems = Problems()
    rows = listed(root)
    all_units = units(root)
    tested = {u for u in all_units if os.path.exists(os.path.join(root, "tests", "unit", os.path.dirname(u),
                                                                  f"test_{os.path.basename(u)}.cpp"))}
    for unit in sorted(all_units - tested - set(rows)):
        problems.add(f"lib/{unit} has no tests/unit/{os.path.dirname(unit)}/test_{os.path.basename(unit)}.cpp "
                     "and no row in tests/unit/README.md saying why")
    for unit, reason in sorted(rows.items()):
        if unit not in all_units:
            problems.add(f"tests/unit/README.md lists {unit}, which lib/ does not have")
        elif unit in tested:
            problems.add(f"tests/unit/README.md lists {unit} as untested, but it has its test file now: remove the row")
        for path in re.findall(r"`(tests/[^`]+)`", reason):
            if not os.path.exists(os.path.join(root, path)):
                problems.add(f"tests/unit/README.md, row {unit}: {path} does not exist")
    return problems.report(f"{len(tested)} of {len(all_units)} units have their test file; "
                          f"the other {len(all_units) - len(tested)} say why in tests/unit/README.md")


if __name__ == "__main__":
    sys.exit(main())
