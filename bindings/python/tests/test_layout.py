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


if __name__ == "__main__":
    unittest.main()
