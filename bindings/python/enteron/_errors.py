# SPDX-License-Identifier: Apache-2.0
"""enteron.Error and the status codes of the C API."""
from ._library import lib

OK = 0
ERROR_INVALID_ARGUMENT = 1
ERROR_VERSION = 2
ERROR_PARSE = 3
ERROR_INVALID_SCENE = 4
ERROR_UNSTABLE = 5
ERROR_OUT_OF_MEMORY = 6
ERROR_NOT_FOUND = 7
ERROR_BUFFER_TOO_SMALL = 8
ERROR_INTERNAL = 9
ERROR_BUSY = 10  # another thread is in a driving call (step, add_obstacle, add_tool) on the scene


def status_string(status):
    """The library's short text for a status ("ok", "invalid argument", ...)."""
    return lib.ent_status_string(status).decode()


class Error(Exception):
    """A C API call failed. `status` is its ent_status (enteron.ERROR_*), `status_name` the
    library's name for it, `message` the library's message (ent_last_error) naming the bad
    input, e.g. "intestine.radius must be > 0, got -1"."""

    def __init__(self, status, message, call=None):
        self.status = status
        self.status_name = status_string(status)
        self.message = message
        self.call = call
        where = "%s: " % call if call else ""
        super().__init__("%s%s (%s)" % (where, message, self.status_name))


def check(status, call):
    """Raises Error for a failed status; ent_last_error is read on the same thread, at once."""
    if status != OK:
        raise Error(status, lib.ent_last_error().decode(errors="replace"), call)
