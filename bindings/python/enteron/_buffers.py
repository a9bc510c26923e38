"""Numpy arrays over memory: copies into fresh arrays, and views of library-owned buffers.

The C API copies the axis and the control points into the caller's memory: the binding
hands the library a fresh numpy array to fill (one copy, as in C). Where the C API lends a
buffer it owns, valid until some later call (the skin mesh of ent_skin_mesh, valid until
the next ent_skin_update), the binding must not copy: view() wraps the library's memory
in a read-only numpy array that keeps its owner (the Python handle) alive.
"""
import ctypes

import numpy as np


def new_array(rows, columns, dtype=np.float64):
    """A C-contiguous array to hand to the library, and the pointer to give it."""
    array = np.empty((rows, columns), dtype=dtype)
    return array, array.ctypes.data_as(ctypes.POINTER(np.ctypeslib.as_ctypes_type(dtype)))


def view(address, shape, ctype, owner):
    """A read-only numpy array over `shape` elements of `ctype` at `address`, owned by the
    library, without copying. The array keeps `owner` alive, so the handle that lent the
    memory cannot be collected while the view exists. The data is valid only as long as
    the C API says (e.g. until the next update); the view sees every change in place.
    """
    count = 1
    for extent in shape:
        count *= extent
    if count == 0:
        return np.empty(shape, dtype=np.dtype(ctype))
    if not address:
        raise ValueError("cannot view a NULL buffer")
    memory = (ctype * count).from_address(address)
    memory._enteron_owner = owner  # lives as long as any array over it
    array = np.ctypeslib.as_array(memory).reshape(shape)
    array.flags.writeable = False
    return array
