#!/usr/bin/env python3
"""The README stays readable as plain text and its links to docs/ stay live (issue 51, item 5).

Usage: check_readme_lines.py [PROJECT_DIR]   (default: the directory above tests/)

Fails (exit 1), listing each fault, when
  - a line of README.md outside fenced code blocks (``` or ~~~) is longer than 120 characters
    (long option descriptions belong in docs/cli.md, which the README's table links);
  - a relative link of README.md (inline `[text](target)` or a reference definition
    `[label]: target`) names a file that does not exist;
  - a link to a Markdown file with an anchor (`docs/cli.md#--exact-count`, or `#section` inside
    the README) names no heading of that file. Anchors are GitHub's: the heading's text without
    its Markdown (code spans, emphasis, links keep their text), lower-cased, every character that
    is not a letter, digit, '-', '_' or space dropped, spaces turned into '-', and a repeated
    slug numbered -1, -2, ... in order. Explicit `<a id="...">` / `<a name="...">` anchors count.
"""
import re
import sys
from pathlib import Path

MAX_LINE = 120
FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
HEADING = re.compile(r"^ {0,3}(#{1,6})[ \t]+(.*?)[ \t]*#*[ \t]*$")
HTML_ANCHOR = re.compile(r"<a\s+(?:id|name)\s*=\s*\"([^\"]+)\"", re.IGNORECASE)
INLINE_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE_DEF = re.compile(r"^ {0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$")
CODE_SPAN = re.compile(r"(`+)(.*?)\1")


def outside_fences(lines):
    """(line number, line) for every line outside fenced code blocks."""
    fence = None
    for number, line in enumerate(lines, 1):
        m = FENCE.match(line)
        if fence is None:
            if m:
                fence = m.group(1)
                continue
            yield number, line
        elif m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) \
                and not line.strip()[len(m.group(1)):].strip():
            fence = None


def slug(text):
    """GitHub's anchor for a heading's text."""
    text = CODE_SPAN.sub(lambda m: m.group(2), text)
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)  # links and images keep their text
    text = re.sub(r"<[^>]+>", "", text)  # inline HTML
    text = text.replace("*", "")
    text = text.strip().lower()
    text = "".join(c for c in text if c.isalnum() or c in "-_ ")
    return text.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        seen = {}
        found = set()
        for _, line in outside_fences(path.read_text(encoding="utf-8").split("\n")):
            found.update(HTML_ANCHOR.findall(line))
            m = HEADING.match(line)
            if not m:
                continue
            base = slug(m.group(2))
            n = seen.get(base, 0)
            seen[base] = n + 1
            found.add(base if n == 0 else f"{base}-{n}")
        cache[path] = found
    return cache[path]


def links(line):
    without_code = CODE_SPAN.sub("", line)
    yield from INLINE_LINK.findall(without_code)
    m = REFERENCE_DEF.match(without_code)
    if m:
        yield m.group(1)


def main():
    project = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent
    readme = project / "README.md"
    lines = readme.read_text(encoding="utf-8").split("\n")
    faults = []
    checked = 0
    for number, line in outside_fences(lines):
        if len(line) > MAX_LINE:
            faults.append(f"README.md:{number}: {len(line)} characters (at most {MAX_LINE}): {line[:60]}...")
        for target in links(line):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.IGNORECASE):
                continue  # http:, https:, mailto:
            file_part, _, anchor = target.partition("#")
            path = readme if not file_part else (project / file_part)
            checked += 1
            if not path.exists():
                faults.append(f"README.md:{number}: link to {target}: no file {file_part}")
                continue
            if anchor and path.suffix == ".md" and anchor not in anchors(path):
                faults.append(f"README.md:{number}: link to {target}: no heading with anchor #{anchor}"
                              f" in {path.relative_to(project)}")
    for fault in faults:
        print(fault)
    if faults:
        print(f"check_readme_lines: {len(faults)} fault(s)")
        return 1
    print(f"check_readme_lines: {len(lines)} lines, none over {MAX_LINE} characters outside code blocks;"
          f" {checked} relative links, all to existing files and headings")
    return 0


if __name__ == "__main__":
    sys.exit(main())
