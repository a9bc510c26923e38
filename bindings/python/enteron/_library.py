# SPDX-License-Identifier: Apache-2.0
"""Finds and loads libenteron, declares the C functions, checks the version.

Search order for the library:
  1. the ENTERON_LIBRARY environment variable: the path of the file to load;
  2. next to the package, in the installed layout (cmake --install writes _install.py
     with the library's path relative to this package);
  3. a build tree of the source checkout this package sits in (build/lib, build/*/lib);
  4. the system's search (ctypes.util.find_library, then the SONAME).
"""
import ctypes
import ctypes.util
import glob
import operator
import os

from . import _fields
from . import _structs as s

# The major version this binding speaks; the loaded library must have the same.
SUPPORTED_MAJOR = 0
SONAME = "libenteron.so.%d" % SUPPORTED_MAJOR


def _candidates():
    variable = os.environ.get("ENTERON_LIBRARY")
    if variable:
        yield variable, "ENTERON_LIBRARY"
        return  # an explicit choice is never second-guessed
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        from . import _install
    except ImportError:
        _install = None
    if _install is not None:
        yield os.path.normpath(os.path.join(here, _install.LIBRARY_RELATIVE_PATH)), "installed layout"
    source_root = os.path.dirname(os.path.dirname(os.path.dirname(here)))  # bindings/python/enteron
    for pattern in ("build/lib/" + SONAME, "build/*/lib/" + SONAME):
        for path in sorted(glob.glob(os.path.join(source_root, pattern))):
            # Sanitized builds (presets tsan, asan) cannot be loaded into a plain python3.
            if os.path.basename(os.path.dirname(os.path.dirname(path))) not in ("tsan", "asan"):
                yield path, "build tree"
    found = ctypes.util.find_library("enteron")
    if found:
        yield found, "system (find_library)"
    yield SONAME, "system (SONAME)"


def _load():
    tried = []
    for path, origin in _candidates():
        if origin in ("ENTERON_LIBRARY", "installed layout", "build tree") and not os.path.exists(path):
            tried.append("%s (%s): no such file" % (path, origin))
            continue
        try:
            return ctypes.CDLL(path), path
        except OSError as error:
            tried.append("%s (%s): %s" % (path, origin, error))
    raise ImportError("enteron: cannot load libenteron:\n  " + "\n  ".join(tried) +
                      "\nSet ENTERON_LIBRARY to the path of libenteron.so.%d." % SUPPORTED_MAJOR)


lib, path = _load()

_status = ctypes.c_int32
_scene_p = ctypes.c_void_p
_double_p = ctypes.POINTER(ctypes.c_double)


def _checked_integer(base):
    """A ctypes argument type that refuses a Python integer out of base's range (ctypes
    alone would silently keep its low bits: 2**32 + 1 would become 1)."""
    class Checked(base):
        @classmethod
        def from_param(cls, value):
            number = operator.index(value)
            low, high, label = _fields.bounds(base)
            if not low <= number <= high:
                raise OverflowError("%d is out of range for %s [%d, %d]" % (number, label, low, high))
            return base(number)
    Checked.__name__ = base.__name__
    return Checked


_CHECKED = {ctypes.c_int32: _checked_integer(ctypes.c_int32), ctypes.c_uint32: _checked_integer(ctypes.c_uint32)}


def _declare(name, restype, *argtypes):
    function = getattr(lib, name)
    function.restype = restype
    function.argtypes = [_CHECKED.get(argtype, argtype) for argtype in argtypes]


_declare("ent_version", ctypes.c_uint32)
_declare("ent_status_string", ctypes.c_char_p, _status)
_declare("ent_last_error", ctypes.c_char_p)
_declare("ent_effect_name", ctypes.c_char_p, ctypes.c_int32)
_declare("ent_callbacks_init", _status, ctypes.POINTER(s.ent_callbacks), ctypes.c_uint32)
_declare("ent_scene_desc_init", _status, ctypes.POINTER(s.ent_scene_desc), ctypes.c_uint32)
_declare("ent_scene_create", _status, ctypes.POINTER(s.ent_scene_desc), ctypes.POINTER(_scene_p))
_declare("ent_scene_create_json_with", _status, ctypes.c_char_p, ctypes.c_size_t,
         ctypes.POINTER(s.ent_callbacks), ctypes.POINTER(_scene_p))
_declare("ent_scene_destroy", None, _scene_p)
_declare("ent_scene_step", _status, _scene_p, ctypes.c_double)
_declare("ent_scene_axis", _status, _scene_p, ctypes.c_uint32, _double_p)
_declare("ent_scene_control_points", _status, _scene_p, ctypes.c_uint32, _double_p,
         ctypes.POINTER(ctypes.c_uint32))
_declare("ent_scene_stats", _status, _scene_p, ctypes.POINTER(s.ent_stats))
_declare("ent_scene_effect_stats", _status, _scene_p, ctypes.c_int32, ctypes.POINTER(s.ent_effect_stats))
_declare("ent_obstacle_desc_init", _status, ctypes.POINTER(s.ent_obstacle_desc), ctypes.c_uint32)
_declare("ent_scene_add_obstacle", _status, _scene_p, ctypes.POINTER(s.ent_obstacle_desc),
         ctypes.POINTER(ctypes.c_int32))
_declare("ent_scene_create_json_file", _status, ctypes.c_char_p, ctypes.POINTER(s.ent_callbacks),
         ctypes.POINTER(_scene_p))
_declare("ent_scene_remove_obstacle", _status, _scene_p, ctypes.c_int32)
_declare("ent_obstacle_set_pose", _status, _scene_p, ctypes.c_int32, _double_p, _double_p)
_declare("ent_obstacle_set_velocity", _status, _scene_p, ctypes.c_int32, _double_p, _double_p)
_declare("ent_obstacle_set_friction", _status, _scene_p, ctypes.c_int32, ctypes.c_double)
_declare("ent_scene_obstacle_count", _status, _scene_p, ctypes.POINTER(ctypes.c_uint32))
_declare("ent_obstacle_pose", _status, _scene_p, ctypes.c_int32, _double_p, _double_p)
_declare("ent_obstacle_mesh", _status, _scene_p, ctypes.c_int32, ctypes.c_uint32, _double_p,
         ctypes.POINTER(ctypes.c_uint32), ctypes.c_uint32, ctypes.POINTER(ctypes.c_uint32),
         ctypes.POINTER(ctypes.c_uint32))
_declare("ent_scene_set_gravity", _status, _scene_p, _double_p)
_declare("ent_scene_pin_point", _status, _scene_p, ctypes.c_uint32, ctypes.c_int32)
_declare("ent_scene_unpin_point", _status, _scene_p, ctypes.c_uint32)
_declare("ent_scene_attach_mesentery", _status, _scene_p, ctypes.c_int32)
_declare("ent_scene_attach_clamped_end", _status, _scene_p, ctypes.c_int32, ctypes.c_int32)
_declare("ent_tool_desc_init", _status, ctypes.POINTER(s.ent_tool_desc), ctypes.c_uint32)
_declare("ent_tool_add", _status, _scene_p, ctypes.POINTER(s.ent_tool_desc), ctypes.POINTER(ctypes.c_int32))
_declare("ent_tool_set_pose", _status, _scene_p, ctypes.c_int32, _double_p, _double_p)
_declare("ent_tool_wrench", _status, _scene_p, ctypes.c_int32, _double_p, _double_p)
_declare("ent_tool_grasp", _status, _scene_p, ctypes.c_int32)
_declare("ent_tool_release", _status, _scene_p, ctypes.c_int32)
_declare("ent_tool_state", _status, _scene_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_int32))
_declare("ent_tool_read_feedback", _status, _scene_p, ctypes.c_int32, ctypes.POINTER(s.ent_tool_feedback))
_declare("ent_scene_contacts", _status, _scene_p, ctypes.c_uint32, ctypes.c_void_p, ctypes.POINTER(ctypes.c_uint32))
_declare("ent_scene_contact_summary", _status, _scene_p, ctypes.POINTER(s.ent_contact_summary))
_declare("ent_tool_read_contacts", _status, _scene_p, ctypes.c_int32, ctypes.POINTER(s.ent_tool_contacts))
_declare("ent_scene_save_state", _status, _scene_p, ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_size_t))
_declare("ent_scene_restore_state", _status, _scene_p, ctypes.c_void_p, ctypes.c_size_t)
_declare("ent_tool_stiffness", _status, _scene_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_double))
_declare("ent_tool_read_stats", _status, _scene_p, ctypes.c_int32, ctypes.POINTER(s.ent_tool_stats))
_declare("ent_tool_remove", _status, _scene_p, ctypes.c_int32)
_declare("ent_scene_tool_count", _status, _scene_p, ctypes.POINTER(ctypes.c_int32))
_exposure_p = ctypes.c_void_p
_declare("ent_exposure_desc_init", _status, ctypes.POINTER(s.ent_exposure_desc), ctypes.c_uint32)
_declare("ent_exposure_create", _status, _scene_p, ctypes.POINTER(s.ent_exposure_desc), ctypes.POINTER(_exposure_p))
_declare("ent_exposure_destroy", None, _exposure_p)
_declare("ent_scene_exposure", _status, _scene_p, _exposure_p, _double_p, ctypes.POINTER(s.ent_exposure_result))
_skin_p = ctypes.c_void_p
_declare("ent_skin_desc_init", _status, ctypes.POINTER(s.ent_skin_desc), ctypes.c_uint32)
_declare("ent_skin_create", _status, _scene_p, ctypes.POINTER(s.ent_skin_desc), ctypes.POINTER(_skin_p))
_declare("ent_skin_update", _status, _skin_p)
_declare("ent_skin_mesh", _status, _skin_p, ctypes.POINTER(s.ent_mesh_view))
_declare("ent_skin_metrics", _status, _skin_p, ctypes.POINTER(s.ent_skin_metrics))
_declare("ent_skin_destroy", None, _skin_p)

version = lib.ent_version()
if version >> 16 != SUPPORTED_MAJOR:
    raise ImportError("enteron: %s is version %d.%d.%d; this binding needs major version %d"
                      % (path, version >> 16, (version >> 8) & 0xFF, version & 0xFF, SUPPORTED_MAJOR))
