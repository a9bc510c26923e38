#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Checks that every source file says its licence in its first line.

    check_spdx.py --root SOURCE_DIR [--fix]

Every source file of the tree (the files git tracks; every file when there is no git)
starts with the line `SPDX-License-Identifier: Apache-2.0` in its language's comment:

    // ...    C, C++, C#, the LCM types (.lcm); or /* ... */ (the public C headers, which
              compile as C89 too, and every file whose own comments are /* ... */)
    # ...     Python, shell, CMake (CMakeLists.txt, .cmake, .cmake.in), pkg-config
              templates (.pc.in), suppression files (.supp), and scripts without an
              extension that start with a #! line
    /* ... */ linker version scripts (.map)

A file that starts with a #! line has it on its second line. Data and prose (JSON, CSV,
Markdown, meshes, images, saved corpora) are not source files. With --fix the line is
added where it is missing (what a newcomer runs after adding files).

Python 3 standard library only. Prints one line per file without it and exits 1 if any.
"""
import argparse
import os
import subprocess
import sys

IDENTIFIER = "SPDX-License-Identifier: Apache-2.0"
SLASHES = f"// {IDENTIFIER}"
HASH = f"# {IDENTIFIER}"
BLOCK = f"/* {IDENTIFIER} */"

# The comments each kind of file may take, by how its name ends (--fix writes the first,
# or the block comment in a file that opens with one).
C_FAMILY = (SLASHES, BLOCK)
BY_ENDING = [
    ((".c", ".h", ".cpp", ".hpp", ".cc", ".cs", ".lcm"), C_FAMILY),
    ((".py", ".sh", ".cmake", ".cmake.in", ".pc.in", ".supp"), (HASH,)),
    ((".map",), (BLOCK,)),
]
BY_NAME = {"CMakeLists.txt": (HASH,)}


def tracked_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], check=True, capture_output=True).stdout
        return [name for name in out.decode("utf-8").split("\0") if name]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for directory, subdirectories, names in os.walk(root):
            subdirectories[:] = [d for d in subdirectories if d != ".git" and not d.startswith("build")]
            files += [os.path.relpath(os.path.join(directory, n), root) for n in names]
        return files


def expected_lines(root, path):
    """The SPDX lines the file may have, or None when it is not a source file."""
    name = os.path.basename(path)
    if name in BY_NAME:
        return BY_NAME[name]
    for endings, line in BY_ENDING:
        if name.endswith(endings):
            return line
    if "." not in name:
        try:
            with open(os.path.join(root, path), "rb") as f:
                if f.read(2) == b"#!":
                    return (HASH,)
        except OSError:
            return None
    return None


def check(root, path, accepted, fix):
    full = os.path.join(root, path)
    with open(full, encoding="utf-8", errors="surrogateescape") as f:
        text = f.read()
    lines = text.split("\n")
    at = 1 if lines and lines[0].startswith("#!") else 0
    if len(lines) > at and lines[at] in accepted:
        return True
    if fix:
        block = BLOCK in accepted and len(lines) > at and lines[at].startswith("/*")
        lines.insert(at, BLOCK if block else accepted[0])
        with open(full, "w", encoding="utf-8", errors="surrogateescape") as f:
            f.write("\n".join(lines))
    return False


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", required=True)
    parser.add_argument("--fix", action="store_true")
    arguments = parser.parse_args()
    missing = []
    checked = 0
    for path in sorted(tracked_files(arguments.root)):
        accepted = expected_lines(arguments.root, path)
        if accepted is None or not os.path.isfile(os.path.join(arguments.root, path)):
            continue
        checked += 1
        if not check(arguments.root, path, accepted, arguments.fix):
            missing.append(f"{path}: its first line (after a #! line) must be \"{accepted[0]}\""
                           + (f" or \"{accepted[1]}\"" if len(accepted) > 1 else ""))
    for problem in missing:
        print(f"check_spdx: {problem}{' (added)' if arguments.fix else ''}", file=sys.stderr)
    if missing and not arguments.fix:
        print(f"check_spdx: {len(missing)} of {checked} source files lack their SPDX line "
              f"(tests/docs/check_spdx.py --root . --fix adds it)", file=sys.stderr)
        return 1
    print(f"check_spdx: {checked} source files, each with its SPDX line")
    return 0


if __name__ == "__main__":
    sys.exit(main())
