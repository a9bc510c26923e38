"""The zero-copy view of library-owned memory (for buffers the C API lends, such as the
skin mesh): the view sees changes in place, is read-only and keeps its owner alive."""
import ctypes
import gc
import unittest
import weakref

from enteron import _buffers


class Owner:
    """Stands in for the handle that lends the memory (e.g. a Skin)."""

    def __init__(self, count):
        self.memory = (ctypes.c_float * count)()


class View(unittest.TestCase):
    def test_view_sees_updates_without_copying(self):
        owner = Owner(12)
        array = _buffers.view(ctypes.addressof(owner.memory), (4, 3), ctypes.c_float, owner)
        self.assertEqual(array.shape, (4, 3))
        self.assertEqual(array.ctypes.data, ctypes.addressof(owner.memory))  # the same memory
        owner.memory[7] = 2.5  # the "library" updates its buffer
        self.assertEqual(array[2, 1], 2.5)
        with self.assertRaises(ValueError):
            array[0, 0] = 1.0  # read-only: the library owns it

    def test_view_keeps_its_owner_alive(self):
        owner = Owner(6)
        owner.memory[5] = 4.0
        alive = weakref.ref(owner)
        array = _buffers.view(ctypes.addressof(owner.memory), (2, 3), ctypes.c_float, owner)
        del owner
        gc.collect()
        self.assertIsNotNone(alive())
        self.assertEqual(array[1, 2], 4.0)
        del array
        gc.collect()
        self.assertIsNone(alive())

    def test_null_and_empty(self):
        with self.assertRaises(ValueError):
            _buffers.view(0, (2, 3), ctypes.c_float, None)
        self.assertEqual(_buffers.view(0, (0, 3), ctypes.c_float, None).shape, (0, 3))


if __name__ == "__main__":
    unittest.main()
