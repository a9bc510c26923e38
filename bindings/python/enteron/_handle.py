# SPDX-License-Identifier: Apache-2.0
"""The life cycle every handle class of the binding shares (Scene, Skin): a context
manager, closed at exit or when collected, and refusing calls once closed. A subclass sets
self._handle and defines close(), which must be idempotent."""


class OwnedHandle:
    _handle = None

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

    def _live(self):
        if not self._handle:
            raise ValueError(f"operation on a closed enteron.{type(self).__name__}")
        return self._handle
