# SPDX-License-Identifier: Apache-2.0
"""Evaluations kept on disk, so that an interrupted run resumes from what it had computed.

A record's key is the sha256 of what determines its result exactly: for a fit, the
experiment's identity, the library's sha256 and the parameter vector's bits (float64,
little-endian), so a value that differs in its last bit is another record, and a rebuilt
library starts afresh. One file per record, dir/ab/abcdef... (the key's first two hex
digits name a subfolder), written to a temporary name and renamed: a run killed in the
middle of a write leaves no half record, and two processes may share the folder.

Resuming needs nothing else: the search is deterministic, so a second run asks for the same
evaluations in the same order, finds the finished ones here at once, and computes the rest.
"""
import hashlib
import os
import tempfile


def key(*parts):
    """The sha256 (hex) of parts (bytes or str), each length-prefixed so that no two lists of
    parts give the same stream."""
    digest = hashlib.sha256()
    for part in parts:
        data = part.encode() if isinstance(part, str) else bytes(part)
        digest.update(len(data).to_bytes(8, "little"))
        digest.update(data)
    return digest.hexdigest()


class DiskCache:
    """get(key) -> bytes or None; put(key, bytes). directory None: a cache that keeps nothing."""

    def __init__(self, directory):
        self.directory = directory
        self.hits = 0
        self.stored = 0
        if directory is not None:
            os.makedirs(directory, exist_ok=True)

    def _path(self, record_key):
        return os.path.join(self.directory, record_key[:2], record_key[2:])

    def get(self, record_key):
        if self.directory is None:
            return None
        try:
            with open(self._path(record_key), "rb") as file:
                record = file.read()
        except FileNotFoundError:
            return None
        self.hits += 1
        return record

    def put(self, record_key, record):
        if self.directory is None:
            return
        path = self._path(record_key)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=os.path.dirname(path), prefix=".partial-")
        try:
            with os.fdopen(handle, "wb") as file:
                file.write(record)
            os.replace(temporary, path)
        except BaseException:
            os.unlink(temporary)
            raise
        self.stored += 1
