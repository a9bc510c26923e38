# SPDX-License-Identifier: Apache-2.0
"""Numpy arrays of what the library hands over: always arrays that own their memory.

The C API copies the axis and the control points into the caller's memory: the binding
hands the library a fresh numpy array to fill (one copy, as in C). Where the C API lends a
buffer it owns (the skin mesh of ent_skin_mesh, valid until the next ent_skin_update or
ent_skin_destroy), the binding copies it out at once: a numpy array cannot be revoked,
and one that still pointed into the library's memory after that memory was reused or
freed would read garbage or crash the interpreter. A Python user can never touch freed
memory through the package.
"""
import ctypes

import numpy as np


def new_array(rows, columns, dtype=np.float64):
    """A C-contiguous array to hand to the library, and the pointer to give it."""
    array = np.empty((rows, columns), dtype=dtype)
    return array, array.ctypes.data_as(ctypes.POINTER(np.ctypeslib.as_ctypes_type(dtype)))


def copy(address, shape, ctype):
    """A read-only numpy array of its own holding `shape` elements of `ctype` copied from
    `address` (memory the library lends for the duration of the call)."""
    count = 1
    for extent in shape:
        count *= extent
    array = np.empty(shape, dtype=np.dtype(ctype))
    if count == 0:
        return array
    if not address:
        raise ValueError("cannot copy a NULL buffer")
    ctypes.memmove(array.ctypes.data, address, count * ctypes.sizeof(ctype))
    array.flags.writeable = False
    return array
