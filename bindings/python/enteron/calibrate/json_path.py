# SPDX-License-Identifier: Apache-2.0
"""Numbers of a JSON document named by a path: how an experiment says which constants of
its scene a fit may change.

Two spellings, both naming one number:
    intestine.bend_stiffness        keys joined by dots, list indices in brackets:
    environment[0].friction         gravity[2]
    /environment/0/friction         a JSON Pointer (RFC 6901: ~1 is "/", ~0 is "~")

The path must exist in the document and end at a number: a path that does not is refused
with a message naming the first part that is missing and what is there instead, so a typo
("bend_stifness") is caught before any simulation runs.
"""
import copy
import numbers
import re

_DOTTED_PART = re.compile(r"([^.\[\]]+)|\[(\d+)\]")


class PathError(ValueError):
    """A path that is malformed, or does not name a number of the document."""


def parse(path):
    """The parts of a path (str keys and int indices), in order."""
    if not isinstance(path, str) or not path:
        raise PathError("a path must be a non-empty string, got %r" % (path,))
    if path.startswith("/"):
        parts = []
        for token in path[1:].split("/"):
            token = token.replace("~1", "/").replace("~0", "~")
            parts.append(int(token) if token.isdigit() else token)
        return tuple(parts)
    parts, position = [], 0
    while position < len(path):
        if parts and path[position] == ".":
            position += 1
        match = _DOTTED_PART.match(path, position)
        if match is None or match.end() == position:
            raise PathError("%r is not a path: expected a key or [index] at character %d" % (path, position + 1))
        parts.append(match.group(1) if match.group(1) is not None else int(match.group(2)))
        position = match.end()
    return tuple(parts)


def spell(parts):
    """The dotted spelling of parts: ("environment", 0, "friction") -> environment[0].friction."""
    text = ""
    for part in parts:
        text += "[%d]" % part if isinstance(part, int) else ("." if text else "") + part
    return text


def _step(node, part, parts_so_far):
    where = spell(parts_so_far) or "the document"
    if isinstance(node, dict):
        if not isinstance(part, str) or part not in node:
            raise PathError("%s has no key %r (it has: %s)" % (where, part, ", ".join(sorted(node)) or "nothing"))
        return node[part]
    if isinstance(node, list):
        if not isinstance(part, int) or not 0 <= part < len(node):
            raise PathError("%s is a list of %d element(s): no element %r" % (where, len(node), part))
        return node[part]
    raise PathError("%s is %r, not an object or a list: it has no part %r" % (where, node, part))


def get(document, parts):
    """The number at parts; PathError if there is none."""
    node = document
    for i, part in enumerate(parts):
        node = _step(node, part, parts[:i])
    if isinstance(node, bool) or not isinstance(node, numbers.Real):
        raise PathError("%s is %r, not a number" % (spell(parts), node))
    return float(node)


def set_number(document, parts, value):
    """Replaces the number at parts with value (in place); PathError if there is none."""
    get(document, parts)
    node = document
    for i, part in enumerate(parts[:-1]):
        node = _step(node, part, parts[:i])
    node[parts[-1]] = float(value)


def add_number(document, parts, value):
    """Sets the number at parts, adding its last key if the object above it lacks it (the
    object itself must exist: adding it could turn an effect on); PathError otherwise."""
    node = document
    for i, part in enumerate(parts[:-1]):
        node = _step(node, part, parts[:i])
    if isinstance(node, dict) and isinstance(parts[-1], str) and parts[-1] not in node:
        node[parts[-1]] = float(value)
        return
    set_number(document, parts, value)


def with_numbers(document, parts_list, values):
    """A deep copy of document with the number at each parts set to the matching value."""
    document = copy.deepcopy(document)
    for parts, value in zip(parts_list, values):
        set_number(document, parts, value)
    return document
