# SPDX-License-Identifier: Apache-2.0
"""Python values into C integers: range-checked against the C type, the field or argument
named. ctypes alone keeps the low bits of an integer too large for its type (2**32 + 10
into a uint32_t field becomes 10, 2**40 becomes 0, -1 becomes 4294967295), so a
description would silently say something else than what was written."""
import ctypes
import operator

_INTEGER_CODES = "bBhHiIlLqQ"


def is_integer_type(ctype):
    """True for the ctypes integer types (c_int32, c_uint32, c_uint64, ...)."""
    return getattr(ctype, "_type_", None) in tuple(_INTEGER_CODES)


def bounds(ctype):
    """(low, high, C name) of a ctypes integer type: c_uint32 -> (0, 2**32 - 1, "uint32_t")."""
    bits = 8 * ctypes.sizeof(ctype)
    if ctype._type_.isupper():
        return 0, 2**bits - 1, "uint%d_t" % bits
    return -2**(bits - 1), 2**(bits - 1) - 1, "int%d_t" % bits


def checked_integer(ctype, value, name):
    """value as a Python int that fits ctype; TypeError (not an integer) or OverflowError
    (out of range) naming `name` otherwise. bool counts as an integer (0 or 1)."""
    try:
        number = operator.index(value)
    except TypeError:
        raise TypeError("%s must be an integer, got %r" % (name, value)) from None
    low, high, c_name = bounds(ctype)
    if not low <= number <= high:
        raise OverflowError("%s must fit %s [%d, %d], got %d" % (name, c_name, low, high, number))
    return number


def set_field(struct, field, value, name=None):
    """struct.field = value, with an integer field range-checked against its C type and
    named `name` (default: the struct's type and the field, "ent_skin_desc.segments")."""
    ctype = dict(type(struct)._fields_).get(field)
    if ctype is not None and is_integer_type(ctype):
        value = checked_integer(ctype, value, name or "%s.%s" % (type(struct).__name__, field))
    setattr(struct, field, value)
