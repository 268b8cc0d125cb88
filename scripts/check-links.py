#!/usr/bin/env python3
"""Checks that every relative link in the project's documentation resolves: the file or folder
exists, and a #anchor names a heading of the target (GitHub's anchors: lower case, punctuation
dropped, spaces as hyphens, -1, -2 ... for repeats). Web links are not followed.

    scripts/check-links.py [FILE.md ...]   # default: README.md, docs/*.md, bench/results/README.md,
                                           # qml/README.md
Exits 1 listing each broken link as FILE:LINE: target (what is wrong); ctest runs it (check_links).
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_FILES = ["README.md", "docs/*.md", "bench/results/README.md", "qml/README.md"]

FENCE = re.compile(r"^\s*(```|~~~)")
INLINE_CODE = re.compile(r"`[^`]*`")
# [text](target "title") and ![alt](target); the text may hold one level of brackets.
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^\s*\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"<a\s+(?:name|id)=\"([^\"]+)\"")


def github_anchor(heading):
    text = re.sub(r"<[^>]+>", "", heading)                   # inline HTML
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)   # links keep their text
    text = text.replace("`", "").lower()
    text = re.sub(r"[^\w\- ]", "", text)                     # \w keeps letters of every script
    return text.replace(" ", "-")


def prose_lines(path):
    """(line number, text) outside fenced code blocks, with inline code removed."""
    in_fence = False
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if FENCE.match(line):
            in_fence = not in_fence
            continue
        if not in_fence:
            yield number, INLINE_CODE.sub("", line)


_anchors_of = {}  # path -> its anchors, each target read once


def anchors(path):
    cache = _anchors_of
    if path not in cache:
        seen = {}
        found = set()
        for _, line in prose_lines(path):
            found.update(HTML_ANCHOR.findall(line))
            match = HEADING.match(line)
            if not match:
                continue
            slug = github_anchor(match.group(2))
            count = seen.get(slug, 0)
            seen[slug] = count + 1
            found.add(slug if count == 0 else f"{slug}-{count}")
        cache[path] = found
    return cache[path]


def check(path):
    problems = []
    for number, line in prose_lines(path):
        targets = LINK.findall(line)
        reference = REFERENCE.match(line)
        if reference:
            targets.append(reference.group(1))
        for target in targets:
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.IGNORECASE):  # http:, https:, mailto:
                continue
            file_part, _, anchor = target.partition("#")
            resolved = (path.parent / file_part).resolve() if file_part else path
            where = f"{path.relative_to(ROOT)}:{number}: {target}"
            if not resolved.exists():
                shown = resolved.relative_to(ROOT) if resolved.is_relative_to(ROOT) else resolved
                problems.append(f"{where} (no such file: {shown})")
            elif anchor and resolved.suffix == ".md" and anchor not in anchors(resolved):
                problems.append(f"{where} (no heading in {resolved.relative_to(ROOT)} has the anchor #{anchor})")
            elif anchor and resolved.suffix != ".md" and not re.fullmatch(r"L\d+(-L\d+)?", anchor):
                problems.append(f"{where} (#{anchor} in a file that is not Markdown)")
    return problems


def main(arguments):
    files = [Path(a).resolve() for a in arguments] or sorted(
        p for pattern in DEFAULT_FILES for p in ROOT.glob(pattern))
    missing = [str(f) for f in files if not f.is_file()]
    if missing:
        print("no such documentation file: " + ", ".join(missing), file=sys.stderr)
        return 1
    problems = [problem for f in files for problem in check(f)]
    for problem in problems:
        print(problem, file=sys.stderr)
    checked = ", ".join(str(f.relative_to(ROOT)) for f in files)
    print(f"{len(problems)} broken link(s) in {checked}" if problems else f"every relative link resolves in {checked}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
