#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Checks that the documentation says what the code does.

    check_docs.py --root SOURCE_DIR CHECK [--table ENTERON_SCENE_TABLE] [--run "NAME=COMMAND"]
                  [--not-run NAME REASON]

CHECK is one of:
  header     every function a public header exports (declared with an ENT_*API macro in
             include/enteron/*.h) has a doc comment (/** ... */) right above it;
  json_keys  every key of the scene's description table (lib/scene/scene_table.h: the
             JSON loader reads by it), at every level, is in its section of
             docs/scene-json.md, and so is every value of a key that takes a choice of
             names; and every message `PATH must be one of "a", "b", got "x"` the page
             quotes lists the table's choices for that key (needs --table, the built
             enteron_scene_table that prints it);
  links      every relative link and image of README.md and docs/*.md leads to a file or
             folder that exists, and its #anchor to a heading (or an <a name>/id) there;
  doc_paths  every docs/*.md that a header, a source file or a document names (in a
             comment, in text: not only links) exists;
  readme_example
             the C program of README.md is examples/minimal.c, character for character
             (but for the file's SPDX licence line);
  example_outputs
             every output examples/README.md quotes (its table's last column) is printed by
             a run of that example: each example of the table is either run (--run
             "NAME=COMMAND", NAME as in the table's first column, e.g. python/skin.py, the
             command line split as a shell would) or named with the reason it is not
             (--not-run NAME REASON). A quoted line must be a line
             the run printed, character for character; where the row says its figures
             "depend on the machine", any number stands for any number.

The JSON keys come from the table itself, printed by tests/docs/print_scene_table.cpp: a
new row (a new key) without its line in the documentation fails here.

Python 3 standard library only. Prints one line per problem and exits 1 if there is any.
"""
import argparse
import json
import os
import re
import subprocess
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

def read_table(program):
    """The scene table's keys, as print_scene_table prints them: path -> {"keys": [...],
    "choices": {key: [names]}}."""
    output = subprocess.run([program], check=True, capture_output=True, text=True).stdout
    return json.loads(output)


def sections(text):
    """Heading text -> the text under it, up to the next heading of any level."""
    lines = text.splitlines()
    marks = [(number, heading) for number, _, heading in headings(text)]
    result = {}
    for i, (number, heading) in enumerate(marks):
        end = marks[i + 1][0] - 1 if i + 1 < len(marks) else len(lines)
        result[heading] = "\n".join(lines[number:end])
    return result


def check_json_keys(root, table_program):
    problems = Problems()
    if not table_program:
        problems.add("json_keys needs --table (the built enteron_scene_table)")
        return problems.report("")
    found = read_table(table_program)
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
                problems.add(f"docs/scene-json.md, section {heading}: the table has the key "
                             f"\"{key}\" ({name + '.' if name else ''}{key}), which is not documented there")
        for key, choices in sorted(entry["choices"].items()):
            for choice in choices:
                values += 1
                if f"\"{choice}\"" not in section:
                    problems.add(f"docs/scene-json.md, section {heading}: the table has "
                                 f"{key} \"{choice}\", which is not documented there")
    quoted = check_quoted_choices(found, read(doc_path), problems)
    return problems.report(f"{keys} JSON keys and {values} named values in {len(found)} places, "
                           f"each in its section of docs/scene-json.md; {quoted} quoted choice messages, "
                           "each the loader's")


QUOTED_CHOICE = re.compile(r"`(([\w.\[\]]+) must be one of (?:\"[^\"]*\"(?:, )?)+, got \"([^\"]*)\")`")


def check_quoted_choices(table, text, problems):
    """Every `PATH must be one of "a", ..., got "x"` the page quotes lists the choices the
    table has for the key at PATH, in its order: a list that lost a newer choice (an
    obstacle type) is caught."""
    count = 0
    for number, line, _ in markdown_lines(text):
        for match in QUOTED_CHOICE.finditer(line):
            message, path, _ = match.groups()
            parts = re.sub(r"\[\d+\]", "", path).split(".")
            entry = table.get(".".join(parts[:-1]))
            choices = entry["choices"].get(parts[-1]) if entry else None
            if choices is None:
                problems.add(f"docs/scene-json.md:{number}: quotes `{message}`, but the table has no choice at {path}")
                continue
            count += 1
            quoted = re.findall(r'"([^"]*)"', message.split(" must be one of ", 1)[1].rsplit(", got ", 1)[0])
            if quoted != list(choices):
                problems.add(f"docs/scene-json.md:{number}: quotes the choices of {path} as {quoted}, "
                             f"the table has {list(choices)}")
    return count


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


# ---------------------------------------------------------------- paths of docs

DOC_PATH = re.compile(r"\bdocs/[A-Za-z0-9_.-]+\.md\b")
# Where docs are named: headers, sources, the binding, examples, scripts and the documents
# (the CHANGELOG is history: it may name what was renamed since).
DOC_PATH_PLACES = ("include", "lib", "bindings", "examples", "apps", "bench", "scripts", "tests", "docs")
DOC_PATH_SUFFIXES = (".h", ".hpp", ".c", ".cpp", ".py", ".md", ".lcm", ".cmake", ".txt", ".sh", ".json")


def named_doc_paths(root):
    """(file, line number, docs/*.md) for every mention outside build trees."""
    files = [os.path.join(root, "README.md")]
    for place in DOC_PATH_PLACES:
        for directory, subdirectories, names in os.walk(os.path.join(root, place)):
            subdirectories[:] = [d for d in subdirectories if not d.startswith((".", "build"))]
            files += [os.path.join(directory, n) for n in sorted(names) if n.endswith(DOC_PATH_SUFFIXES)]
    for path in files:
        try:
            text = read(path)
        except (UnicodeDecodeError, OSError):
            continue
        for number, line in enumerate(text.splitlines(), 1):
            for match in DOC_PATH.finditer(line):
                yield os.path.relpath(path, root), number, match.group(0)


def check_doc_paths(root):
    problems = Problems()
    count = 0
    for where, number, path in named_doc_paths(root):
        count += 1
        if not os.path.isfile(os.path.join(root, path)):
            problems.add(f"{where}:{number}: names {path}, which does not exist")
    return problems.report(f"{count} mentions of docs/*.md, each an existing file")


# ---------------------------------------------------------------- example outputs

NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?")


def table_cells(line):
    """The cells of a markdown table row; an escaped \\| stays inside its cell."""
    cells = re.split(r"(?<!\\)\|", line.strip())
    return [cell.strip().replace("\\|", "|") for cell in cells[1:-1]]


def quoted_outputs(readme):
    """(line number, example name, [quoted outputs], machine dependent) per table row."""
    for number, line, fenced in markdown_lines(readme):
        if fenced or not line.startswith("| `"):
            continue
        cells = table_cells(line)
        if len(cells) < 3:
            continue
        name = re.match(r"`([^`]+)`", cells[0]).group(1)
        quotes = re.findall(r"`([^`]+)`", cells[-1])
        yield number, name, quotes, "depend on the machine" in cells[-1]


def output_pattern(quote, machine_dependent):
    """A regular expression a printed line must match in full: the quote itself, or with
    any number for its numbers (and any run of spaces for its own, which numbers of
    another width move) where the figures depend on the machine; "..." stands for anything."""
    parts = []
    for piece in re.split(r"(\.\.\.)", quote):
        if piece == "...":
            parts.append(".*")
            continue
        if not machine_dependent:
            parts.append(re.escape(piece))
            continue
        at = 0
        for match in NUMBER.finditer(piece):
            parts.append(re.sub(r"\\ (?:\\ )+", r"\\s+", re.escape(piece[at:match.start()])))
            parts.append(r"[-+]?\d+(?:\.\d+)?")
            at = match.end()
        parts.append(re.sub(r"\\ (?:\\ )+", r"\\s+", re.escape(piece[at:])))
    return re.compile("".join(parts))


def check_example_outputs(root, runs, not_run):
    import subprocess
    problems = Problems()
    readme_path = os.path.join(root, "examples", "README.md")
    checked = 0
    rows = list(quoted_outputs(read(readme_path)))
    for number, name, quotes, machine_dependent in rows:
        if name in not_run:
            continue
        if name not in runs:
            problems.add(f"examples/README.md:{number}: quotes what {name} prints, but no run of it is checked: "
                         "give it --run (or --not-run with the reason) in tests/docs/docs.cmake")
            continue
        try:
            result = subprocess.run(runs[name], capture_output=True, text=True, timeout=120)
        except (OSError, subprocess.TimeoutExpired) as error:
            problems.add(f"examples/README.md:{number}: cannot run {name} ({' '.join(runs[name])}): {error}")
            continue
        printed = (result.stdout + result.stderr).splitlines()
        if result.returncode != 0:
            problems.add(f"examples/README.md:{number}: {name} exited with status {result.returncode}")
        for quote in quotes:
            checked += 1
            pattern = output_pattern(quote, machine_dependent)
            if not any(pattern.fullmatch(line.rstrip()) for line in printed):
                import difflib
                closest = next(iter(difflib.get_close_matches(quote, printed, n=1, cutoff=0.0)), None)
                problems.add(f"examples/README.md:{number}: {name} does not print {quote!r}"
                             + (f" (it prints {closest!r})" if closest else ""))
    for name in list(runs) + list(not_run):
        if name not in {row[1] for row in rows}:
            problems.add(f"tests/docs/docs.cmake names the example {name}, which examples/README.md's table lacks")
    return problems.report(f"{checked} quoted outputs of {len(runs)} examples printed by their runs "
                           f"({len(not_run)} examples not run here: {', '.join(sorted(not_run))})")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", required=True)
    parser.add_argument("--table")
    parser.add_argument("--run", action="append", default=[], metavar="NAME=COMMAND")
    parser.add_argument("--not-run", nargs=2, action="append", default=[], metavar=("NAME", "REASON"))
    parser.add_argument("check", choices=["header", "json_keys", "links", "doc_paths", "readme_example",
                                          "example_outputs"])
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    if args.check == "header":
        return check_header(root)
    if args.check == "json_keys":
        return check_json_keys(root, args.table)
    if args.check == "links":
        return check_links(root)
    if args.check == "doc_paths":
        return check_doc_paths(root)
    if args.check == "example_outputs":
        import shlex
        runs = {name: shlex.split(command) for name, _, command in (run.partition("=") for run in args.run)}
        return check_example_outputs(root, runs, dict(args.not_run))
    return check_readme_example(root)


if __name__ == "__main__":
    sys.exit(main())
