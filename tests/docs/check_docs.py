#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Checks that the documentation says what the code does.

    check_docs.py --root SOURCE_DIR CHECK [--library LIBENTERON]

CHECK is one of:
  header     every function a public header exports (declared with an ENT_*API macro in
             include/enteron/*.h) has a doc comment (/** ... */) right above it;
  json_keys  every key the JSON loader accepts, at every level, is in its section of
             docs/scene-json.md, and so is every value of a key that takes a choice of
             names (needs --library, the built libenteron);
  links      every relative link and image of README.md and docs/*.md leads to a file or
             folder that exists, and its #anchor to a heading (or an <a name>/id) there;
  readme_example
             the C program of README.md is examples/minimal.c, character for character
             (but for the file's SPDX licence line).

The JSON keys come from the loader itself, not from reading its source: a document with an
unknown key is refused with the keys allowed at that place ("unknown key "x" in intestine
(expected one of: length, radius, ...)"), the message users see. Asking the built library
at each level finds every key, whatever shape the loader's code takes, and cannot list a
key the loader does not accept.

Python 3 standard library only. Prints one line per problem and exits 1 if there is any.
"""
import argparse
import ctypes
import json
import os
import re
import sys


class Problems:
    def __init__(self):
        self.lines = []

    def add(self, text):
        self.lines.append(text)

    def report(self, ok_message):
        for line in self.lines:
            print(f"check_docs: {line}", file=sys.stderr)
        if self.lines:
            print(f"check_docs: {len(self.lines)} problem(s)", file=sys.stderr)
            return 1
        print(f"check_docs: {ok_message}")
        return 0


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


# ---------------------------------------------------------------- markdown

FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def markdown_lines(text):
    """(line number, line, inside a fenced code block) for every line."""
    fenced = False
    for number, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line):
            yield number, line, True
            fenced = not fenced
            continue
        yield number, line, fenced


def headings(text):
    """(line number, level, text) of every ATX heading outside code blocks."""
    for number, line, fenced in markdown_lines(text):
        match = None if fenced else HEADING.match(line)
        if match:
            yield number, len(match.group(1)), match.group(2)


def slug(heading):
    """The anchor GitHub gives a heading: lower case, punctuation dropped, spaces to '-'."""
    text = re.sub(r"<[^>]+>", "", heading).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(text):
    seen = {}
    found = set()
    for _, _, heading in headings(text):
        base = slug(heading)
        count = seen.get(base, 0)
        seen[base] = count + 1
        found.add(base if count == 0 else f"{base}-{count}")
    found.update(re.findall(r"<a\s+(?:name|id)=\"([^\"]+)\"", text))
    found.update(re.findall(r"\sid=\"([^\"]+)\"", text))
    return found


# ---------------------------------------------------------------- header

EXPORT = re.compile(r"^\s*ENT\w*_API\b")
FUNCTION_NAME = re.compile(r"\b(ent_\w+)\s*\(")


def check_header(root):
    problems = Problems()
    include = os.path.join(root, "include", "enteron")
    count = 0
    for name in sorted(os.listdir(include)):
        if not name.endswith(".h"):
            continue
        path = os.path.join(include, name)
        lines = read(path).splitlines()
        for index, line in enumerate(lines):
            if not EXPORT.match(line):
                continue
            declaration = " ".join(lines[index:index + 4])
            match = FUNCTION_NAME.search(declaration)
            where = f"include/enteron/{name}:{index + 1}"
            if not match:
                problems.add(f"{where}: an exported declaration whose function name this check cannot read")
                continue
            count += 1
            function = match.group(1)
            above = lines[index - 1].rstrip() if index > 0 else ""
            if not above.endswith("*/"):
                problems.add(f"{where}: {function} has no doc comment (/** ... */) right above it")
                continue
            start = index - 1
            while start >= 0 and "/*" not in lines[start]:
                start -= 1
            opening = lines[start].lstrip() if start >= 0 else ""
            if not opening.startswith("/**") or opening.startswith("/**<"):
                problems.add(f"{where}: the comment above {function} is not a doc comment (/** ... */)")
                continue
            body = " ".join(lines[start:index])
            body = re.sub(r"/\*\*|\*/|\*", " ", body).strip()
            if len(body.split()) < 3:
                problems.add(f"{where}: the doc comment of {function} says nothing: {body!r}")
    if count == 0:
        problems.add(f"no exported function (ENT_*API) found in {include}: has the export macro changed?")
    return problems.report(f"{count} exported functions, each with a doc comment")


# ---------------------------------------------------------------- JSON keys

PROBE = "zz_undocumented_probe"
UNKNOWN_KEY = re.compile(r"unknown key \"" + PROBE + r"\" .*\(expected one of: (.*)\)$")
CHOICES = re.compile(r"must be one of ((?:\"[^\"]*\"(?:, )?)+), got \"" + PROBE + "\"")


class Loader:
    """Asks the library's JSON loader, through the C API, what it accepts."""

    def __init__(self, library):
        self.lib = ctypes.CDLL(library)
        self.lib.ent_scene_create_json.argtypes = [ctypes.c_char_p, ctypes.c_size_t,
                                                   ctypes.POINTER(ctypes.c_void_p)]
        self.lib.ent_scene_create_json.restype = ctypes.c_int32
        self.lib.ent_last_error.restype = ctypes.c_char_p
        self.lib.ent_scene_destroy.argtypes = [ctypes.c_void_p]

    def error(self, document):
        """The loader's message for this document, or None if it makes a scene."""
        text = json.dumps(document).encode()
        scene = ctypes.c_void_p()
        if self.lib.ent_scene_create_json(text, len(text), ctypes.byref(scene)) == 0:
            self.lib.ent_scene_destroy(scene)
            return None
        return self.lib.ent_last_error().decode()

    def keys(self, place):
        """The keys allowed in the object that place(object) puts in a document, or None
        if the loader does not read an object with keys there."""
        match = UNKNOWN_KEY.search(self.error(place({PROBE: 0})) or "")
        if not match:
            return None
        return [key for key in match.group(1).split(", ") if key]

    def choices(self, place):
        """The names allowed for the value that place(value) puts in a document, or []."""
        match = CHOICES.search(self.error(place(PROBE)) or "")
        return re.findall(r"\"([^\"]*)\"", match.group(1)) if match else []


def discover(loader, place, name, found):
    """Fills found[name] with the keys the loader accepts in the object that place(object)
    puts in a document, and the named values of those keys; then the same for every object,
    array of objects, or array of typed objects (an obstacle's "type") below it. False if
    the loader reads no object with keys there."""
    keys = loader.keys(place)
    if keys is None:
        return False
    entry = found.setdefault(name, {"keys": set(), "choices": {}})
    entry["keys"].update(keys)
    for key in keys:
        child = f"{name}.{key}" if name else key
        inside = lambda value, key=key: place({key: value})  # noqa: E731
        element = lambda value, key=key: place({key: [value]})  # noqa: E731
        if discover(loader, inside, child, found) or discover(loader, element, child, found):
            continue
        kinds = loader.choices(lambda value, element=element: element({"type": value}))
        if kinds:
            typed = found.setdefault(child, {"keys": set(), "choices": {}})
            typed["keys"].add("type")
            typed["choices"]["type"] = kinds
            for kind in kinds:
                discover(loader, lambda value, element=element, kind=kind: element({"type": kind, **value}),
                         child, found)
            continue
        values = loader.choices(inside)
        if values:
            entry["choices"][key] = values
    return True


def sections(text):
    """Heading text -> the text under it, up to the next heading of any level."""
    lines = text.splitlines()
    marks = [(number, heading) for number, _, heading in headings(text)]
    result = {}
    for i, (number, heading) in enumerate(marks):
        end = marks[i + 1][0] - 1 if i + 1 < len(marks) else len(lines)
        result[heading] = "\n".join(lines[number:end])
    return result


def check_json_keys(root, library):
    problems = Problems()
    if not library:
        problems.add("json_keys needs --library (the built libenteron)")
        return problems.report("")
    loader = Loader(library)
    found = {}
    if not discover(loader, lambda value: value, "", found):
        problems.add(f"the loader's answer to an unknown top-level key is not the expected message: "
                     f"{loader.error({PROBE: 0})!r}")
        return problems.report("")
    doc_path = os.path.join(root, "docs", "scene-json.md")
    by_heading = sections(read(doc_path))
    keys = values = 0
    for name, entry in sorted(found.items()):
        heading = "Top level" if not name else f"`{name}`"
        section = next((body for title, body in by_heading.items() if title == heading), None)
        if section is None:
            if entry["keys"] or entry["choices"]:
                problems.add(f"docs/scene-json.md has no section \"{heading}\" for the keys "
                             f"{', '.join(sorted(entry['keys']))}")
            continue
        for key in sorted(entry["keys"]):
            keys += 1
            if f"`{key}`" not in section:
                problems.add(f"docs/scene-json.md, section {heading}: the loader accepts the key "
                             f"\"{key}\" ({name + '.' if name else ''}{key}), which is not documented there")
        for key, choices in sorted(entry["choices"].items()):
            for choice in choices:
                values += 1
                if f"\"{choice}\"" not in section:
                    problems.add(f"docs/scene-json.md, section {heading}: the loader accepts "
                                 f"{key} \"{choice}\", which is not documented there")
    return problems.report(f"{keys} JSON keys and {values} named values in {len(found)} places, "
                           "each in its section of docs/scene-json.md")


# ---------------------------------------------------------------- links

INLINE_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE_LINK = re.compile(r"^\s*\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+\"[^\"]*\")?\s*$")


def link_targets(text):
    """(line number, target) of every link and image outside code and HTML comments."""
    text = re.sub(r"<!--.*?-->", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    for number, line, fenced in markdown_lines(text):
        if fenced:
            continue
        line = re.sub(r"(`+).*?\1", "", line)
        for match in INLINE_LINK.finditer(line):
            yield number, match.group(1)
        match = REFERENCE_LINK.match(line)
        if match:
            yield number, match.group(1)


def check_links(root):
    problems = Problems()
    files = [os.path.join(root, "README.md")]
    docs = os.path.join(root, "docs")
    files += sorted(os.path.join(docs, name) for name in os.listdir(docs) if name.endswith(".md"))
    count = 0
    for path in files:
        relative = os.path.relpath(path, root)
        for number, target in link_targets(read(path)):
            if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):
                continue  # a URL (https:, mailto:): not checked here
            count += 1
            file_part, _, anchor = target.partition("#")
            resolved = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) if file_part else path
            if not os.path.exists(resolved):
                problems.add(f"{relative}:{number}: link to {target}: {os.path.relpath(resolved, root)} does not exist")
                continue
            if anchor and resolved.endswith(".md") and anchor not in anchors(read(resolved)):
                problems.add(f"{relative}:{number}: link to {target}: {os.path.relpath(resolved, root)} "
                             f"has no heading with the anchor #{anchor}")
    return problems.report(f"{count} relative links in {len(files)} files, each resolves")


# ---------------------------------------------------------------- README example

def check_readme_example(root):
    problems = Problems()
    blocks, block, language = [], None, None
    for number, line, fenced in markdown_lines(read(os.path.join(root, "README.md"))):
        if FENCE.match(line):
            if block is None:
                block, language = [], line.strip().lstrip("`~").strip()
            else:
                blocks.append((number, language, "\n".join(block) + "\n"))
                block = None
        elif block is not None:
            block.append(line)
    programs = [(number, code) for number, language, code in blocks
                if language == "c" and re.search(r"\bint\s+main\s*\(", code)]
    example = read(os.path.join(root, "examples", "minimal.c"))
    # Its licence line (tests/docs/check_spdx.py) is the file's, not the program's.
    example = re.sub(r"\A/\* SPDX-License-Identifier: [^*]*\*/\n", "", example)
    if len(programs) != 1:
        problems.add(f"README.md has {len(programs)} C programs (```c blocks with main); "
                     "it must have one, examples/minimal.c")
    elif programs[0][1] != example:
        number, code = programs[0]
        shown, real = code.splitlines(), example.splitlines()
        first = next((i for i, (a, b) in enumerate(zip(shown, real)) if a != b), min(len(shown), len(real)))
        problems.add(f"README.md: the C program ending at line {number} differs from examples/minimal.c "
                     f"from its line {first + 1}: README {shown[first] if first < len(shown) else '(end)'!r}, "
                     f"file {real[first] if first < len(real) else '(end)'!r}")
    return problems.report("the C program of README.md is examples/minimal.c")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", required=True)
    parser.add_argument("--library")
    parser.add_argument("check", choices=["header", "json_keys", "links", "readme_example"])
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    if args.check == "header":
        return check_header(root)
    if args.check == "json_keys":
        return check_json_keys(root, args.library)
    if args.check == "links":
        return check_links(root)
    return check_readme_example(root)


if __name__ == "__main__":
    sys.exit(main())
