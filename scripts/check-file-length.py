#!/usr/bin/env python3
"""Lists the source files over 800 lines that do not say why at their top: a file that long must
carry, in its first 15 lines, a comment line starting "Over 800 lines because" (after the comment
marker: //, #). Checks .cpp, .h, .qml and .py files under simcore/, app/, tests/, bench/ and fuzz/.
Also keeps README.md, the project's front door, under 15 KB (what it links to goes in docs/).

    scripts/check-file-length.py     # exits 1 listing each such file with its length
ctest runs it (check_file_length).
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FOLDERS = ["simcore", "app", "tests", "bench", "fuzz"]
SUFFIXES = {".cpp", ".h", ".qml", ".py"}
MAX_LINES = 800
REASON_WITHIN = 15  # lines from the top
README_MAX_BYTES = 15 * 1024
REASON = re.compile(r"^\s*(//|#)\s*Over 800 lines because \S")


def main():
    unexplained = []
    for folder in FOLDERS:
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix not in SUFFIXES or not path.is_file():
                continue
            lines = path.read_text(encoding="utf-8").splitlines()
            if len(lines) > MAX_LINES and not any(REASON.match(l) for l in lines[:REASON_WITHIN]):
                unexplained.append(f"{path.relative_to(ROOT)}: {len(lines)} lines")
    readme_bytes = (ROOT / "README.md").stat().st_size
    if readme_bytes >= README_MAX_BYTES:
        unexplained.append(f"README.md: {readme_bytes} bytes, over {README_MAX_BYTES} (move detail into docs/)")
    for entry in unexplained:
        print(entry, file=sys.stderr)
    if unexplained:
        print(f"{len(unexplained)} file(s) too long: a source file over {MAX_LINES} lines needs an 'Over 800 lines "
              f"because ...' line in its first {REASON_WITHIN} lines (split the file, or say why it is one)",
              file=sys.stderr)
        return 1
    print(f"every source file over {MAX_LINES} lines says why; README.md is {readme_bytes} bytes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
