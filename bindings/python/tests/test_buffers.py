# SPDX-License-Identifier: Apache-2.0
"""Arrays of memory the library lends (the skin mesh): copies that own their data, so that
they stay valid whatever the library does with its buffer afterwards."""
import ctypes
import unittest

from enteron import _buffers


class Copy(unittest.TestCase):
    def test_copy_owns_its_data(self):
        memory = (ctypes.c_float * 12)(*range(12))
        array = _buffers.copy(ctypes.addressof(memory), (4, 3), ctypes.c_float)
        self.assertEqual(array.shape, (4, 3))
        self.assertNotEqual(array.ctypes.data, ctypes.addressof(memory))
        self.assertTrue(array.flags.owndata)
        memory[7] = 99.0  # the library reuses its buffer...
        self.assertEqual(array[2, 1], 7.0)  # ...the copy keeps what was lent
        with self.assertRaises(ValueError):
            array[0, 0] = 1.0  # read-only, as the C view is const
        del memory  # the library frees its buffer: the copy is unaffected
        self.assertEqual(float(array.sum()), float(sum(range(12))))

    def test_null_and_empty(self):
        with self.assertRaises(ValueError):
            _buffers.copy(0, (2, 3), ctypes.c_float)
        self.assertEqual(_buffers.copy(0, (0, 3), ctypes.c_float).shape, (0, 3))


if __name__ == "__main__":
    unittest.main()
