# SPDX-License-Identifier: Apache-2.0
"""The ctypes mirrors have the C compiler's layout, and the binding loaded the library
it was told to, with the header's version."""
import ctypes
import json
import os
import re
import subprocess
import unittest

import enteron
from enteron import _structs


class Layout(unittest.TestCase):
    def test_every_struct_matches_the_c_layout(self):
        tool = os.environ.get("ENTERON_STRUCT_LAYOUT")
        if not tool:
            self.skipTest("ENTERON_STRUCT_LAYOUT (the struct_layout program) is not set")
        c_layout = json.loads(subprocess.run([tool], check=True, capture_output=True, text=True).stdout)
        self.assertEqual(set(c_layout), {cls.__name__ for cls in _structs.ALL})
        for cls in _structs.ALL:
            with self.subTest(struct=cls.__name__):
                expected = c_layout[cls.__name__]
                self.assertEqual(ctypes.sizeof(cls), expected["size"])
                self.assertEqual([name for name, _ in cls._fields_], list(expected["fields"]))
                for name, (offset, size) in expected["fields"].items():
                    self.assertEqual(getattr(cls, name).offset, offset, name)
                    self.assertEqual(getattr(cls, name).size, size, name)


class Library(unittest.TestCase):
    def test_loaded_from_enteron_library(self):
        wanted = os.environ.get("ENTERON_LIBRARY")
        if not wanted:
            self.skipTest("ENTERON_LIBRARY is not set")
        self.assertEqual(os.path.realpath(enteron.library_path), os.path.realpath(wanted))

    def test_version_is_the_headers(self):
        header = os.environ.get("ENTERON_HEADER")
        if not header:
            self.skipTest("ENTERON_HEADER is not set")
        with open(header) as file:
            text = file.read()
        parts = tuple(int(re.search(r"#define ENT_VERSION_%s (\d+)" % part, text).group(1))
                      for part in ("MAJOR", "MINOR", "PATCH"))
        self.assertEqual(enteron.version, parts)
        self.assertEqual(enteron.version[0], enteron.SUPPORTED_MAJOR)

    def test_constants_are_the_headers(self):
        # Every integer constant of the header (ENT_EFFECT_TOOLS, ENT_EFFECT_COUNT, ENT_ERROR_*,
        # ...) has its twin in the package with the same value: a constant added to the header
        # and not here fails.
        header = os.environ.get("ENTERON_HEADER")
        if not header:
            self.skipTest("ENTERON_HEADER is not set")
        with open(header) as file:
            constants = dict(re.findall(r"^#define ENT_([A-Z0-9_]+) +(\d+)\b", file.read(), re.MULTILINE))
        constants = {name: int(value) for name, value in constants.items() if not name.startswith("VERSION_")}
        self.assertIn("EFFECT_COUNT", constants)
        for name, value in sorted(constants.items()):
            with self.subTest(constant="ENT_" + name):
                self.assertEqual(getattr(enteron, name, None), value)
        # And every effect the binding knows has the library's name.
        names = [enteron.effect_name(n) for n in range(enteron.EFFECT_COUNT)]
        self.assertNotIn(None, names)
        self.assertEqual(names[enteron.EFFECT_TOOLS], "tools")
        self.assertIsNone(enteron.effect_name(enteron.EFFECT_COUNT))


if __name__ == "__main__":
    unittest.main()
