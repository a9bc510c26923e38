# SPDX-License-Identifier: Apache-2.0
"""Reads LCM log files -- lcm-logger's recordings and the bridge's journal -- and decodes
Enteron's messages with the Python types lcm-gen makes from bindings/lcm (the package
enteron_lcm.enteron, built next to this module). Debian has no `lcm` Python module; the
generated types need only `struct`, and so does this reader.

    from enteron_lcm import log
    for event in log.read_events("session.lcmlog"):
        message = log.decode(event.data)  # an enteron_lcm.enteron.*_t, or None
        ...

The file format (lcm_eventlog): each event is, big-endian, the int32 magic 0xEDA1DA01,
an int64 event number, an int64 timestamp (us since the epoch, when the logger received
it), an int32 channel length, an int32 data length, the channel, then the data.
"""

import collections
import struct

from enteron_lcm.enteron import (journal_step_t, journal_tool_t, mesh_t, scene_state_t, server_status_t, session_t,
                                 tool_command_t, tool_feedback_t)

MAGIC = 0xEDA1DA01
_HEADER = struct.Struct(">IqqII")
_LONGEST_CHANNEL = 255

Event = collections.namedtuple("Event", "number timestamp_us channel data")

# Every message type of bindings/lcm that travels on its own (tool_state_t is nested).
TYPES = (tool_command_t, tool_feedback_t, scene_state_t, mesh_t, session_t, server_status_t, journal_tool_t,
         journal_step_t)
_BY_FINGERPRINT = {message_type._get_packed_fingerprint(): message_type for message_type in TYPES}


class LogError(ValueError):
    """The file is not an LCM log, or is damaged at the given byte offset."""


def read_events(path):
    """Yields every Event of the log file at `path`, in order. Raises LogError at the first
    damaged event (a truncated file ends with LogError too: the last event is incomplete)."""
    with open(path, "rb") as file:
        data = file.read()
    offset = 0
    while offset < len(data):
        if len(data) - offset < _HEADER.size:
            raise LogError("%s: byte %d: a truncated event header" % (path, offset))
        magic, number, timestamp_us, channel_length, data_length = _HEADER.unpack_from(data, offset)
        if magic != MAGIC:
            raise LogError("%s: byte %d: no event starts here (bad magic)" % (path, offset))
        start = offset + _HEADER.size
        if not 1 <= channel_length <= _LONGEST_CHANNEL or start + channel_length + data_length > len(data):
            raise LogError("%s: byte %d: channel length %d, data length %d past the end of the file"
                           % (path, offset, channel_length, data_length))
        channel = data[start:start + channel_length].decode("utf-8", "replace")
        payload = data[start + channel_length:start + channel_length + data_length]
        yield Event(number, timestamp_us, channel, payload)
        offset = start + channel_length + data_length


def message_type(data):
    """The generated type whose fingerprint `data` starts with, or None."""
    return _BY_FINGERPRINT.get(bytes(data[:8]))


def decode(data):
    """Decodes one of Enteron's messages by its fingerprint; None for any other bytes,
    ValueError for bytes that carry the fingerprint but do not decode (a damaged message)."""
    found = message_type(data)
    if found is None:
        return None
    try:
        return found.decode(bytes(data))
    except (struct.error, ValueError, UnicodeDecodeError) as error:
        raise ValueError("a damaged %s: %s" % (found.__name__, error)) from error


def messages(path, channels=None):
    """Yields (event, message) for the events of `path` that decode as Enteron messages,
    optionally only on the given channel names."""
    for event in read_events(path):
        if channels is not None and event.channel not in channels:
            continue
        message = decode(event.data)
        if message is not None:
            yield event, message
