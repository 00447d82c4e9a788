#!/usr/bin/env python3
"""The documentation's code is the code that is built and run: every ```cpp and ```cmake block of
README.md and docs/*.md is a region of a file that the test suite or the consumer project compiles and
runs, or says why it is not one.

  <!-- snippet: examples/consumer/saturating_conductance.hpp#law -->   the block equals that region
  <!-- excerpt: examples/consumer/saturating.json -->                  its lines, "..." for a gap, are the
                                                                       file's lines in that order (any language)
  <!-- not a snippet: a one-line signature -->                         a fragment, left alone

The marker is the last non-blank line before the fence, or ends that line. A region is marked in its file
by `// [snippet NAME]` ... `// [snippet NAME end]` (`#` in CMake); a name opened again continues the
region (its parts each lose their common indentation), regions may overlap, and marker lines are never
part of one. A block is compared with its common indentation and trailing spaces stripped.

Usage: scripts/check_snippets.py [--root DIR] [--fix] [--self-test]
  --fix        rewrites every snippet block from its region (then check again)
  --self-test  checks the checker: a copy of the documents passes, and fails once a line is changed
"""
import argparse
import re
import shutil
import sys
import tempfile
from pathlib import Path

CHECKED_LANGUAGES = {"cpp", "c++", "cmake"}
FENCE = re.compile(r"^(\s*)```(\S*)\s*$")
MARKER = re.compile(r"<!--\s*(snippet|excerpt|not a snippet):\s*(.*?)\s*-->\s*$")
REGION = re.compile(r"^\s*(?://|#)\s*\[snippet ([\w.-]+)( end)?\]\s*$")


def documents(root):
    return [root / "README.md"] + sorted((root / "docs").glob("*.md"))


def dedent(lines):
    lines = [line.rstrip() for line in lines]
    indents = [len(line) - len(line.lstrip()) for line in lines if line.strip()]
    cut = min(indents, default=0)
    return [line[cut:] for line in lines]


class Block:
    def __init__(self, doc, start, end, indent, language, marker):
        self.doc, self.start, self.end, self.indent, self.language = doc, start, end, indent, language
        self.kind, self.argument = marker if marker else (None, None)

    def where(self, root):
        return f"{self.doc.relative_to(root)}:{self.start + 1}"


def blocks_of(doc):
    """The fenced blocks of a markdown file, each with the marker that precedes it."""
    lines = doc.read_text().splitlines()
    found, i = [], 0
    while i < len(lines):
        opening = FENCE.match(lines[i])
        if not opening or not opening.group(2):
            i += 1
            continue
        end = next((j for j in range(i + 1, len(lines)) if FENCE.match(lines[j]) and not FENCE.match(lines[j]).group(2)),
                   None)
        if end is None:
            raise SystemExit(f"{doc}:{i + 1}: a code block that is never closed")
        previous = next((lines[j] for j in range(i - 1, -1, -1) if lines[j].strip()), "")
        marker = MARKER.search(previous)
        found.append(Block(doc, i, end, opening.group(1), opening.group(2).lower(),
                           (marker.group(1), marker.group(2)) if marker else None))
        i = end + 1
    return found


def regions_of(path):
    """name -> its lines: each part dedented on its own, marker lines of any region left out."""
    parts, open_parts = {}, {}
    for number, line in enumerate(path.read_text().splitlines(), 1):
        marker = REGION.match(line)
        if marker:
            name, closing = marker.group(1), bool(marker.group(2))
            if closing != (name in open_parts):
                raise ValueError(f"{path}:{number}: region '{name}' {'closed before it opens' if closing else 'opened twice'}")
            if closing:
                parts.setdefault(name, []).append(dedent(open_parts.pop(name)))
            else:
                open_parts[name] = []
            continue
        for lines in open_parts.values():
            lines.append(line)
    if open_parts:
        raise ValueError(f"{path}: region '{next(iter(open_parts))}' is never closed")
    return {name: [line for part in part_list for line in part] for name, part_list in parts.items()}


def region_text(root, argument, cache):
    """The lines of `path#NAME`, or a ValueError saying what is missing."""
    path_text, _, name = argument.partition("#")
    path = root / path_text
    if not name:
        raise ValueError(f"'{argument}' names no region (path#NAME)")
    if not path.is_file():
        raise ValueError(f"'{path_text}' does not exist")
    if path not in cache:
        cache[path] = regions_of(path)
    if name not in cache[path]:
        known = ", ".join(sorted(cache[path])) or "none"
        raise ValueError(f"'{path_text}' has no region '{name}' (its regions: {known})")
    return cache[path][name]


def is_excerpt(block_lines, path):
    """The block's lines, '...' lines being gaps, are lines of the file in that order."""
    wanted = [line.strip() for line in block_lines if line.strip() and line.strip() != "..."]
    file_lines = iter(line.strip() for line in path.read_text().splitlines())
    return all(any(line == candidate for candidate in file_lines) for line in wanted)


def first_difference(shown, region):
    for i, (a, b) in enumerate(zip(shown, region)):
        if a != b:
            return i, a, b
    i = min(len(shown), len(region))
    return i, shown[i] if i < len(shown) else "<end of block>", region[i] if i < len(region) else "<end of region>"


def check_block(root, block, lines, cache):
    """The problem of one block, or None."""
    shown = dedent(lines[block.start + 1:block.end])
    if block.kind == "not a snippet":
        return None if block.argument else f"{block.where(root)}: 'not a snippet' says no reason"
    if block.kind == "excerpt":
        path = root / block.argument
        if not path.is_file():
            return f"{block.where(root)}: excerpt of '{block.argument}', which does not exist"
        return None if is_excerpt(shown, path) else f"{block.where(root)}: not an excerpt of '{block.argument}'"
    if block.kind != "snippet":
        if block.language not in CHECKED_LANGUAGES:
            return None
        return (f"{block.where(root)}: a ```{block.language} block without a marker: precede it with "
                "<!-- snippet: path#NAME --> or <!-- not a snippet: reason -->")
    try:
        region = region_text(root, block.argument, cache)
    except ValueError as error:
        return f"{block.where(root)}: {error}"
    if shown == region:
        return None
    i, got, want = first_difference(shown, region)
    return (f"{block.where(root)}: differs from {block.argument} at block line {i + 1}:\n"
            f"    README/docs: {got}\n    region:      {want}\n  (scripts/check_snippets.py --fix rewrites it)")


def check(root, fix=False):
    """Checks (or rewrites) every document under root; returns the problems and the count of snippets."""
    problems, snippets, cache = [], 0, {}
    for doc in documents(root):
        lines = doc.read_text().splitlines()
        found = []
        for block in reversed(blocks_of(doc)):  # from the end, so that a rewrite keeps the earlier line numbers
            problem = check_block(root, block, lines, cache)
            snippets += block.kind == "snippet"
            if problem and fix and block.kind == "snippet" and "differs from" in problem:
                region = region_text(root, block.argument, cache)
                lines[block.start + 1:block.end] = [(block.indent + line).rstrip() for line in region]
                continue
            if problem:
                found.append(problem)
        problems += reversed(found)
        if fix and "\n".join(lines) + "\n" != doc.read_text():
            doc.write_text("\n".join(lines) + "\n")
    return problems, snippets


def copy_documents(root, to):
    """README.md, docs/*.md and every file their snippets name, under the same relative paths."""
    for doc in documents(root):
        target = to / doc.relative_to(root)
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(doc, target)
        for block in blocks_of(doc):
            if block.kind in ("snippet", "excerpt"):
                source = block.argument.partition("#")[0]
                (to / source).parent.mkdir(parents=True, exist_ok=True)
                if (root / source).is_file():
                    shutil.copy(root / source, to / source)


def self_test(root):
    """A block changed on purpose, a region changed, an unmarked block: each fails; --fix repairs the first."""
    def expect(condition, what):
        print(f"self-test: {'ok' if condition else 'FAILED'}: {what}")
        return condition

    with tempfile.TemporaryDirectory() as work:
        copy = Path(work)
        copy_documents(root, copy)
        ok = expect(check(copy)[0] == [], "the copied documents pass")
        readme = copy / "README.md"
        original = readme.read_text()
        block = next(b for b in blocks_of(readme) if b.kind == "snippet" and b.end - b.start > 2)
        lines = original.splitlines()
        lines[block.start + 2] += "  // a changed line"
        readme.write_text("\n".join(lines) + "\n")
        problems = check(copy)[0]
        ok &= expect(len(problems) == 1 and f"README.md:{block.start + 1}: differs" in problems[0],
                     f"a changed line in the block at README.md:{block.start + 1} fails")
        check(copy, fix=True)
        ok &= expect(check(copy)[0] == [] and readme.read_text() == original, "--fix rewrites it as it was")
        source = copy / block.argument.partition("#")[0]
        source_text = source.read_text()
        region_line = next(line for line in region_text(copy, block.argument, {}) if line.strip())
        source.write_text(source_text.replace(region_line, region_line + " /* changed */", 1))
        ok &= expect(any("differs" in p for p in check(copy)[0]), f"a changed line in {source.relative_to(copy)} fails")
        source.write_text(source_text)
        readme.write_text(original.replace('"phi_s": 3e-5}}', '"phi_s": 4e-5}}', 1))
        ok &= expect(any("not an excerpt" in p for p in check(copy)[0]), "a changed line of a JSON excerpt fails")
        readme.write_text(original + "\n```cpp\nint main() {}\n```\n")
        ok &= expect(any("without a marker" in p for p in check(copy)[0]), "a ```cpp block without a marker fails")
        readme.write_text(original + "\n<!-- snippet: examples/nowhere.cpp#x -->\n```cpp\nint main() {}\n```\n")
        ok &= expect(any("does not exist" in p for p in check(copy)[0]), "a snippet of a missing file fails")
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent)
    parser.add_argument("--fix", action="store_true")
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    root = args.root.resolve()
    if args.self_test:
        return 0 if self_test(root) else 1
    problems, snippets = check(root, fix=args.fix)
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        return 1
    print(f"snippets: {snippets} blocks of README.md and docs/*.md are their regions' code")
    return 0


if __name__ == "__main__":
    sys.exit(main())
