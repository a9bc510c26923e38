# SPDX-License-Identifier: Apache-2.0
"""The life cycle every handle class of the binding shares (Scene, Skin): a context
manager, closed at exit or when collected, and refusing calls once closed.

Calls in flight: ctypes releases the GIL during a C call, so another thread may close the
object while a call on it runs (a thread stepping the scene, another closing it). Every
call therefore runs inside `with self._using() as handle:` (or through self._call), which
counts it in flight; close() refuses every later call at once (ValueError) and destroys the
C handle itself only when the last call in flight returns (at once when none is). The
memory goes then, on the thread of that call; nothing ever reads freed memory.

A subclass calls self._own(handle, destroy) once the C handle exists (destroy: the C
function that frees it) and may extend close(), which is idempotent."""
import threading


class _InFlight:
    """The `with` block of one call: holds the C handle for as long as it runs."""

    __slots__ = ("_owner", "_handle")

    def __init__(self, owner):
        self._owner = owner

    def __enter__(self):
        owner = self._owner
        with owner._lock:
            if not owner._handle:
                raise ValueError(f"operation on a closed enteron.{type(owner).__name__}")
            owner._in_flight += 1
            self._handle = owner._handle
        return self._handle

    def __exit__(self, *exc):
        owner = self._owner
        handle = None
        with owner._lock:
            owner._in_flight -= 1
            if owner._in_flight == 0 and owner._closing is not None:
                handle, owner._closing = owner._closing, None  # the last call of a closed object
        if handle:
            owner._destroy(handle)
        return False


class OwnedHandle:
    _handle = None
    _closing = None     # the C handle of a closed object that calls in flight still use
    _in_flight = 0

    def _own(self, handle, destroy):
        self._lock = threading.Lock()
        self._destroy = destroy
        self._handle = handle

    @property
    def closed(self):
        return not self._handle

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __del__(self):
        self.close()

    def close(self):
        """Closes the object: later calls raise ValueError; the C handle is destroyed now, or
        by the last call in flight on another thread as it returns. Idempotent."""
        lock = getattr(self, "_lock", None)
        if lock is None:  # never owned a handle (its construction failed)
            return
        with lock:
            handle, self._handle = self._handle, None
            if handle and self._in_flight:
                self._closing, handle = handle, None
        if handle:
            self._destroy(handle)

    def _using(self):
        """`with self._using() as handle:` the C handle, counted in flight for the block;
        ValueError if the object is closed."""
        return _InFlight(self)

    def _call(self, function, *arguments):
        """function(handle, *arguments) with the C handle counted in flight."""
        with self._using() as handle:
            return function(handle, *arguments)
